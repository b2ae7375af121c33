// clrt-bench load: how fast scenes are loaded (the .ray file and its OBJ meshes) and their
// geometry built (triangle tables and BVH), separately and together, best of N runs, and once in
// a fresh process. Prints a Markdown table with milliseconds and millions of triangles per second.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <stdexcept>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "cli/whole_number.hpp"
#include "commands.hpp"
#include "geometry/geometry_data.hpp"
#include "math/parallel_for.hpp"

namespace clrt::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Times {
  double load = 1e30, build = 1e30, both = 1e30;
  std::size_t triangles = 0;
};

// Loads the scene and builds its geometry from scratch.
Times one_run(const std::string& path) {
  Times t;
  const auto start = Clock::now();
  const Scene scene = load_scene(path);
  t.load = seconds_since(start);
  const auto build_start = Clock::now();
  const GeometryData geometry = build_geometry(scene);
  t.build = seconds_since(build_start);
  t.both = t.load + t.build;
  t.triangles = geometry.triangle_count();
  return t;
}

// The least time of each step over the runs, and of the two together in one run.
Times best_of(const std::string& path, int runs) {
  Times best;
  for (int r = 0; r < runs; ++r) {
    const Times t = one_run(path);
    best.load = std::min(best.load, t.load);
    best.build = std::min(best.build, t.build);
    best.both = std::min(best.both, t.both);
    best.triangles = t.triangles;
  }
  return best;
}

// One run in a child forked from this process before it has run anything: what a `clrt`
// command pays, with the first touch of every page it fills. (Runs in the same process reuse
// the pages the allocator kept from the runs before: on a 1M-triangle mesh the best of five
// loads about a third faster than a fresh process.)
Times fresh_run(const std::string& path) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw std::runtime_error("no pipe for a fresh run");
  std::fflush(nullptr);  // the child must not write this process's buffers again
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("no fresh process could start");
  if (child == 0) {
    close(pipe_ends[0]);
    int status = 1;
    try {
      const Times t = one_run(path);
      if (write(pipe_ends[1], &t, sizeof t) == static_cast<ssize_t>(sizeof t)) status = 0;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "clrt-bench: %s\n", e.what());
    }
    _exit(status);
  }
  close(pipe_ends[1]);
  Times t;
  const bool complete = read(pipe_ends[0], &t, sizeof t) == static_cast<ssize_t>(sizeof t);
  close(pipe_ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (!complete || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the fresh run of " + path + " failed");
  return t;
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
  // Every fresh run is forked before this process runs anything itself.
  std::vector<Times> fresh;
  for (const std::string& path : o.scenes) fresh.push_back(fresh_run(path));
  // The rows wait for the end, so that the load average at the end comes before the table.
  std::vector<std::string> rows;
  for (std::size_t k = 0; k < o.scenes.size(); ++k) {
    const std::string& path = o.scenes[k];
    const Times b = best_of(path, o.runs);
    const auto rate = [&](double s) { return static_cast<double>(b.triangles) / s / 1e6; };
    char row[640];
    std::snprintf(row, sizeof row, "| %s | %zu | %.1f | %.2f | %.1f | %.2f | %.1f | %.2f | %.1f + %.1f |", path.c_str(),
                  b.triangles, b.load * 1e3, rate(b.load), b.build * 1e3, rate(b.build), b.both * 1e3, rate(b.both),
                  fresh[k].load * 1e3, fresh[k].build * 1e3);
    rows.push_back(row);
  }
  std::printf(", %.2f at the end\n\n", load_average());
  std::printf("| scene | triangles | load ms | load Mtris/s | build ms | build Mtris/s | load + build ms | "
              "load + build Mtris/s | fresh process: load + build ms |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
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
