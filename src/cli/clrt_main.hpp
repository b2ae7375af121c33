// The whole of clrt's command, as main() runs it: the exit status is 0 on success, 1 for a
// runtime failure (device, kernel build, output) and 2 for a usage or scene error.
#pragma once

namespace clrt {

int clrt_main(int argc, char** argv);

}  // namespace clrt
