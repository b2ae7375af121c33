// Every installed clrt program writes its own man page and bash completion, from the very parser
// it runs, when the build asks it with the hidden options `--write-man-page FILE` and
// `--write-bash-completion FILE`
// (tools/cmake/Install.cmake): neither can then fall behind an option, and no program's parser
// has to be linked into another.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/docs/tool_manual.hpp"

#include <string>
#include <vector>

namespace clrt {

// The hidden options, each answered as soon as it is parsed (before any other option's check): the
// page is written and parsing ends as --version ends it (exit status 0, or 1 if FILE cannot be
// written).
void add_cli_docs_option(CLI::App& app, const ToolManual& manual);

// Whether `args` (the words after the program's name) ask for the pages, for a program that must
// know before it starts anything (clrt-mpi, before MPI).
bool asks_for_cli_docs(const std::vector<std::string>& args);

}  // namespace clrt
