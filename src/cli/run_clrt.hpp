// clrt's whole command, once its command line is parsed: every check that can come before the
// work, the render of each frame, the writes, --stats. Returns the exit status (0 ok, 1 runtime
// failure, 2 usage or scene error); errors are printed as "clrt: error: ...", scene errors as
// FILE:LINE:COLUMN: error: ....
#pragma once

#include "cli/options.hpp"

namespace clrt {

int run_clrt(const CliOptions& cli);

}  // namespace clrt
