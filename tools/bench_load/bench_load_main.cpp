// clrt-bench-load: how fast scenes are loaded (the .ray file and its OBJ meshes) and their
// geometry built (triangle tables and BVH), separately and together, best of N runs. Prints a
// Markdown table with milliseconds and millions of triangles per second.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "geometry/geometry_data.hpp"
#include "math/parallel_for.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Best {
  double load = 1e30, build = 1e30, both = 1e30;
};

// Each run loads the scene and builds its geometry from scratch; the least time of each step,
// and of the two together in one run, counts.
Best measure(const std::string& path, int runs, std::size_t& triangles) {
  Best best;
  for (int r = 0; r < runs; ++r) {
    const auto start = Clock::now();
    const clrt::Scene scene = clrt::load_scene(path);
    const double load = seconds_since(start);
    const auto build_start = Clock::now();
    const clrt::GeometryData geometry = clrt::build_geometry(scene);
    const double build = seconds_since(build_start);
    best.load = std::min(best.load, load);
    best.build = std::min(best.build, build);
    best.both = std::min(best.both, load + build);
    triangles = geometry.triangle_count();
  }
  return best;
}

double load_average() {
  double avg[1] = {0};
  return getloadavg(avg, 1) == 1 ? avg[0] : -1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"clrt-bench-load: scene load and geometry build times and rates"};
  std::vector<std::string> scenes;
  int runs = 5;
  unsigned threads = 0;
  app.add_option("scenes", scenes, ".ray files (e.g. clrt-make-scenes' tri-1k.ray ... tri-1m.ray)")->required();
  app.add_option("--runs", runs, "runs per scene; the best counts")->capture_default_str();
  app.add_option("--threads", threads, "threads for the parallel steps (default: one per core)");
  CLI11_PARSE(app, argc, argv);
  clrt::parallel_thread_limit = threads;

  std::printf("%u threads, best of %d runs; load average %.2f at the start", clrt::parallel_threads(), runs,
              load_average());
  std::fflush(stdout);
  std::vector<std::string> rows;
  try {
    for (const std::string& path : scenes) {
      std::size_t triangles = 0;
      const Best b = measure(path, runs, triangles);
      const auto rate = [&](double s) { return static_cast<double>(triangles) / s / 1e6; };
      char row[512];
      std::snprintf(row, sizeof row, "| %s | %zu | %.1f | %.2f | %.1f | %.2f | %.1f | %.2f |", path.c_str(), triangles,
                    b.load * 1e3, rate(b.load), b.build * 1e3, rate(b.build), b.both * 1e3, rate(b.both));
      rows.push_back(row);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "\nclrt-bench-load: %s\n", e.what());
    return 1;
  }
  std::printf(", %.2f at the end\n\n", load_average());
  std::printf("| scene | triangles | load ms | load Mtris/s | build ms | build Mtris/s | load + build ms | "
              "load + build Mtris/s |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& row : rows) std::printf("%s\n", row.c_str());
  return 0;
}
