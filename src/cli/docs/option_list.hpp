// What the man page and the shell completion need of a CLI11 parser, read from the parser itself
// (its options, groups, value kinds and choices) so that neither can fall behind it.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace clrt::cli_docs {

struct OptionEntry {
  std::vector<std::string> names;  // "-o", "--outfile": as typed
  std::string value;               // the value's kind as --help shows it ("UINT"), empty for a flag
  std::vector<std::string> choices;  // the words it accepts, when they are a fixed set
  std::string description;
  std::string group;
};

// Every option --help lists, in its order (hidden ones, without a group, left out), positional
// arguments not included.
std::vector<OptionEntry> listed_options(const CLI::App& app);

}  // namespace clrt::cli_docs
