// clrt: render a .ray or .nff scene with the wavefront OpenCL renderer. (Its body lives in
// clrt_cli, so that this file, compiled last, costs the build no time.)
#include "cli/clrt_main.hpp"

int main(int argc, char** argv) { return clrt::clrt_main(argc, argv); }
