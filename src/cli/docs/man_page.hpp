// A man page (roff, man(7) macros) of a CLI11 parser: its description, synopsis, and every option
// --help lists, in its groups.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace clrt::cli_docs {

// `version` goes in the page's footer; `see_also` is its last section's text.
std::string man_page(const CLI::App& app, const std::string& version, const std::string& see_also);

}  // namespace clrt::cli_docs
