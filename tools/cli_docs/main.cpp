// clrt-cli-docs: writes clrt's man page or its bash completion script, generated at build time
// from the very parser clrt runs (clrt_command_line()), so that both list every option it has.
//   clrt-cli-docs man FILE | clrt-cli-docs bash FILE
#include <fstream>
#include <iostream>

#include "bash_completion.hpp"
#include "cli/options.hpp"
#include "man_page.hpp"
#include "version.hpp"

int main(int argc, char** argv) {
  const std::string kind = argc == 3 ? argv[1] : "";
  if (kind != "man" && kind != "bash") {
    std::cerr << "usage: clrt-cli-docs man|bash FILE\n";
    return 2;
  }
  clrt::CliOptions options;
  clrt::StatsRequest stats;
  const std::unique_ptr<CLI::App> app = clrt::clrt_command_line(options, stats);
  std::ofstream out(argv[2], std::ios::binary);
  if (kind == "man")
    out << clrt::cli_docs::man_page(
        *app, clrt_version_string(),
        "The full description of every option, the exit status and pbrt's spellings: cli.md in "
        "clrt's documentation; the scene format: scene-format.md.");
  else
    out << clrt::cli_docs::bash_completion(*app, {"ray", "RAY", "nff", "NFF"});
  out.close();
  if (!out) {
    std::cerr << "clrt-cli-docs: error: cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
