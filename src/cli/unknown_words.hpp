// When CLI11 refuses a command line, the word to blame. CLI11 reports what it could not place
// ("The following arguments were not expected: scene.ray --resolutoin"), which names the
// scene after a mistyped option took its place; users need the mistyped word itself and the
// name they meant.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace clrt {

// For `args` (the words after the program's name, in order) that `app` failed to parse:
// "unknown option --resolutoin (did you mean --resolution?)" for the first option that
// neither the program nor its chosen command defines, else "unknown command conver (did you
// mean convert?)" when a program of commands got one it does not know ("a command is
// required: convert, info, ..." when it got none), else nothing (CLI11's own message says it
// best). The suggestion is left out when no name is close.
std::optional<std::string> unknown_word_message(const CLI::App& app,
                                                const std::vector<std::string>& args);

}  // namespace clrt
