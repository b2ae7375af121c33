// A man page (roff, man(7) macros) of a CLI11 parser: its description, synopsis, and every option
// --help lists, in its groups; then its exit statuses, examples and related pages.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cli/docs/tool_manual.hpp"

namespace clrt::cli_docs {

// What a page says beyond the parser: its EXIT STATUS, EXAMPLES and SEE ALSO sections.
struct ManPageSections {
  std::vector<ManualLine> exit_status, examples;
  std::string see_also;
};

// `version` goes in the page's footer.
std::string man_page(const CLI::App& app, const std::string& version, const ManPageSections& sections);

}  // namespace clrt::cli_docs
