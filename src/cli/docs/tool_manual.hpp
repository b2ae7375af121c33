// What a program's --help, man page and completion say beyond its parser, in a header of its own
// so that a program's options can name it without CLI11.
#pragma once

#include <string>
#include <vector>

namespace clrt {
namespace cli_docs {

// One paragraph of a list: its term ("2", a command line) and what it means.
struct ManualLine {
  std::string term, text;
};

}  // namespace cli_docs

struct ToolManual {
  std::string page;  // the documentation page that covers the program fully ("docs/images.md")
  std::vector<std::string> positional_extensions;  // the files its completion offers ({}: any)
  // The man page's EXIT STATUS ({}: 0, 1 and 2 as every clrt program uses them) and EXAMPLES.
  std::vector<cli_docs::ManualLine> exit_status, examples;
};

}  // namespace clrt
