// What every clrt program does with its command line: --version naming the commit, errors as
// "NAME: error: ..." with a pointer to --help, an unknown option or command named as such with
// the nearest real name, and exit status 2 for a usage error (0 after --help or --version),
// whatever CLI11 would return.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/docs/cli_docs_option.hpp"

#include <optional>
#include <string>
#include <vector>

namespace clrt {

// Gives `app` the --version flag, the error format, the hidden option that writes its man page
// and completion, and (when `manual` names a page) a --help footer pointing at the man page and
// the installed page; call before adding options.
void identify_tool(CLI::App& app, const ToolManual& manual = {});

// Parses `args` (the words after the program's name): nothing when the program goes on, else
// the status to exit with (the message printed, unless `print` is false: the MPI ranks but
// the first parse the same words and stay silent).
std::optional<int> parse_tool_arguments(CLI::App& app, std::vector<std::string> args,
                                        bool print = true);
std::optional<int> parse_tool_arguments(CLI::App& app, int argc, char** argv);

}  // namespace clrt
