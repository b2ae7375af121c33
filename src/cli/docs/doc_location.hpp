// Where the documentation --help and the man pages name is: a program run from the build tree it
// was built in points at the source tree's README.md and docs/ (they are what it was built
// from), an installed one at the documentation `cmake --install` put beside it.
#pragma once

#include <string>

namespace clrt::cli_docs {

// The folder holding README.md and docs/ for the running executable, decided from its own
// location (/proc/self/exe): the documentation folder at the same place relative to it as the
// install's (bin/ -> share/doc/clrt), when it holds README.md and docs/; else the source tree when
// the executable lies in the build tree; else the configured one (CMAKE_INSTALL_FULL_DOCDIR).
std::string documentation_folder();

// The configured install's documentation folder: what an installed man page names.
std::string installed_documentation_folder();

}  // namespace clrt::cli_docs
