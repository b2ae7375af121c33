// A bash completion script for a CLI11 parser: its option names, the fixed words of options that
// take one (--mode trace|cast|path), file names for other text values, and for the positional
// argument the files ending in `positional_extensions` and folders (any file when it is empty);
// for a program of commands (clrt-img convert), the commands and then each command's own.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace clrt::cli_docs {

// The script defines _NAME (hyphens made underscores) and registers it for the program NAME.
std::string bash_completion(const CLI::App& app, const std::vector<std::string>& positional_extensions);

}  // namespace clrt::cli_docs
