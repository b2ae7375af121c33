// clrt-bench: the benchmarks of scene loading, BVH building and traversal, one subcommand each.
// Each prints a Markdown table. Exit status: 0 success, 1 a scene or the device failed, 2 a
// usage error.
#include <cstdio>
#include <exception>

#include "cli/tool_command_line.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"clrt-bench: scene load, BVH build and ray throughput", "clrt-bench"};
  clrt::identify_tool(app);
  app.require_subcommand(1);
  clrt::bench::Command run;
  clrt::bench::add_bvh(app, run);
  clrt::bench::add_load(app, run);
  if (const auto status = clrt::parse_tool_arguments(app, argc, argv)) return *status;
  try {
    return run();
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "\nclrt-bench: error: %s\n", e.what());
    return 1;
  }
}
