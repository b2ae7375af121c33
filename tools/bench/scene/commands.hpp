// The subcommands of clrt-bench, each of which adds itself to the command line and, when it is
// the one chosen, sets `run` to its measurement (which returns the exit status).
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace clrt::bench {

using Command = std::function<int()>;

// bvh: BVH build time, size and ray throughput through scene_closest_hit / scene_any_hit.
void add_bvh(CLI::App& app, Command& run);

// load: scene load and geometry build times and rates, best of N runs.
void add_load(CLI::App& app, Command& run);

}  // namespace clrt::bench
