// clrt-bench load: how fast scenes are loaded (the .ray file and its OBJ meshes) and their
// geometry built (triangle tables and BVH), separately and together, best of N runs. Prints a
// Markdown table with milliseconds and millions of triangles per second.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "cli/whole_number.hpp"
#include "commands.hpp"
#include "geometry/geometry_data.hpp"
#include "math/parallel_for.hpp"

namespace clrt::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Best {
  double load = 1e30, build = 1e30, both = 1e30;
};

// Each run loads the scene and builds its geometry from scratch; the least time of each step,
// and of the two together in one run, counts.
Best best_of(const std::string& path, int runs, std::size_t& triangles) {
  Best best;
  for (int r = 0; r < runs; ++r) {
    const auto start = Clock::now();
    const Scene scene = load_scene(path);
    const double load = seconds_since(start);
    const auto build_start = Clock::now();
    const GeometryData geometry = build_geometry(scene);
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

struct LoadOptions {
  std::vector<std::string> scenes;
  int runs = 5;
  unsigned threads = 0;
};

int measure_load(const LoadOptions& o) {
  parallel_thread_limit = o.threads;
  std::printf("%u threads, best of %d runs; load average %.2f at the start", parallel_threads(), o.runs,
              load_average());
  std::fflush(stdout);
  // The rows wait for the end, so that the load average at the end comes before the table.
  std::vector<std::string> rows;
  for (const std::string& path : o.scenes) {
    std::size_t triangles = 0;
    const Best b = best_of(path, o.runs, triangles);
    const auto rate = [&](double s) { return static_cast<double>(triangles) / s / 1e6; };
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %zu | %.1f | %.2f | %.1f | %.2f | %.1f | %.2f |", path.c_str(), triangles,
                  b.load * 1e3, rate(b.load), b.build * 1e3, rate(b.build), b.both * 1e3, rate(b.both));
    rows.push_back(row);
  }
  std::printf(", %.2f at the end\n\n", load_average());
  std::printf("| scene | triangles | load ms | load Mtris/s | build ms | build Mtris/s | load + build ms | "
              "load + build Mtris/s |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& row : rows) std::printf("%s\n", row.c_str());
  return 0;
}

}  // namespace

void add_load(CLI::App& app, Command& run) {
  const auto o = std::make_shared<LoadOptions>();
  CLI::App* load = app.add_subcommand("load", "scene load and geometry build times and rates");
  load->add_option("scenes", o->scenes, ".ray files (e.g. clrt-make-scenes' tri-1k.ray ... tri-1m.ray)")->required();
  load->add_option("--runs", o->runs, "runs per scene; the best counts")
      ->transform(whole_number(1, 1000))
      ->capture_default_str();
  load->add_option("--threads", o->threads, "threads for the parallel steps (default: one per core)")
      ->transform(whole_number(1, 4096));
  load->callback([o, &run] { run = [o] { return measure_load(*o); }; });
}

}  // namespace clrt::bench
