#include "cli/docs/cli_docs_option.hpp"

#include <fstream>
#include <iostream>

#include "cli/docs/bash_completion.hpp"
#include "cli/docs/doc_location.hpp"
#include "cli/docs/man_page.hpp"
#include "version.hpp"

namespace clrt {
namespace {

constexpr const char* kManPage = "--write-man-page";
constexpr const char* kCompletion = "--write-bash-completion";

// The page is installed, so it names the documentation where the install puts it.
std::string see_also(const CLI::App& app, const ToolManual& manual) {
  std::string others;
  for (const char* program :
       {"clrt", "clrt-img", "clrt-view", "clrt-experiment", "clrt-make-scenes", "clrt-mpi"})
    if (program != app.get_name()) others += (others.empty() ? "" : ", ") + std::string(program) + "(1)";
  if (manual.page.empty()) return others;
  return "The full description of " + app.get_name() + ": " + manual.page + " in clrt's documentation, " +
         cli_docs::installed_documentation_folder() + "/" + manual.page + ". " + others;
}

// What every clrt program's exit status means, unless its manual says more.
const std::vector<cli_docs::ManualLine>& common_exit_status() {
  static const std::vector<cli_docs::ManualLine> statuses = {
      {"0", "success (and after --help or --version)"},
      {"1", "a failure at run time: a file that cannot be read or written, or whose contents do "
            "not allow the request"},
      {"2", "a usage error: an unknown option, a bad value, a missing argument"}};
  return statuses;
}

}  // namespace

void add_cli_docs_option(CLI::App& app, const ToolManual& manual) {
  CLI::App* const parser = &app;
  const auto add = [&](const char* name, auto page) {
    app.add_option_function<std::string>(
           name,
           [parser, page](const std::string& file) {
             std::ofstream out(file, std::ios::binary);
             out << page(*parser);
             out.close();
             if (!out) {
               std::cerr << parser->get_name() << ": error: cannot write " << file << "\n";
               throw CLI::RuntimeError(1);
             }
             throw CLI::Success();
           },
           "")
        ->trigger_on_parse()
        ->group("");
  };
  add(kManPage, [manual](const CLI::App& program) {
    return cli_docs::man_page(
        program, clrt_version_string(),
        {manual.exit_status.empty() ? common_exit_status() : manual.exit_status, manual.examples,
         see_also(program, manual)});
  });
  add(kCompletion, [manual](const CLI::App& program) {
    return cli_docs::bash_completion(program, manual.positional_extensions);
  });
}

bool asks_for_cli_docs(const std::vector<std::string>& args) {
  return !args.empty() && (args.front() == kManPage || args.front() == kCompletion);
}

}  // namespace clrt
