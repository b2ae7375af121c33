// clrt-bench: renders scenes with the clrt executable, one process per run as a user would,
// and prints a Markdown table: rays by kind, Mrays/s on the device, seconds from command to
// image, and the peak memory of the process.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "bench_json.hpp"
#include "bench_run.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  CLI::App app{"clrt-bench: throughput of clrt on .ray scenes"};
  std::vector<std::string> scenes;
  std::string clrt_exe = CLRT_EXE;
  std::string resolution = "1280x720";
  std::string device = "cpu";
  int runs = 3;
  std::vector<std::string> extra;
  app.add_option("scenes", scenes, ".ray files or folders of them (default: scenes/)");
  app.add_option("--clrt", clrt_exe, "the clrt executable")->capture_default_str();
  app.add_option("--resolution", resolution, "WxH for every scene")->capture_default_str();
  app.add_option("--device", device, "clrt --device SPEC")->capture_default_str();
  app.add_option("--runs", runs, "runs per scene; the fastest is reported")->capture_default_str();
  app.add_option("--extra", extra, "further clrt arguments, e.g. --extra=--spp=4");
  CLI11_PARSE(app, argc, argv);
  if (scenes.empty()) scenes.push_back("scenes");

  std::vector<std::string> files = clrt::bench::expand_scenes(scenes);
  if (files.empty()) {
    std::cerr << "clrt-bench: no .ray scene found\n";
    return 2;
  }
  std::cout << "| scene | camera | shadow | reflection | refraction | Mrays/s | render s | command s | peak MiB |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  int failures = 0;
  for (const std::string& scene : files) {
    const std::string image = (fs::temp_directory_path() / "clrt-bench.png").string();
    std::vector<std::string> args = {clrt_exe, scene, "-o", image, "--resolution", resolution,
                                     "--device", device, "--stats=json", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    clrt::bench::RunResult best;
    for (int r = 0; r < runs; ++r) {
      clrt::bench::RunResult run = clrt::bench::run_process(args);
      if (run.exit_code != 0) {
        best = run;
        break;
      }
      if (r == 0 || run.wall_seconds < best.wall_seconds) best = run;
    }
    const std::string name = fs::path(scene).filename().string();
    if (best.exit_code != 0) {
      std::cout << "| " << name << " | failed with exit code " << best.exit_code << " | | | | | | | |\n";
      ++failures;
      continue;
    }
    const clrt::bench::JsonNumbers j(best.output);
    std::printf("| %s | %.0f | %.0f | %.0f | %.0f | %.2f | %.3f | %.3f | %.0f |\n", name.c_str(),
                j.get("camera"), j.get("shadow"), j.get("reflection"), j.get("refraction"),
                j.get("mrays_per_second"), j.get("render"), best.wall_seconds,
                best.peak_rss_bytes / (1024.0 * 1024.0));
  }
  return failures ? 1 : 0;
}
