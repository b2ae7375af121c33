#include "report.hpp"

#include <cstdio>

#include "scene_summary.hpp"

namespace clrt::compare {
namespace {

double mrays(std::size_t count, double seconds) {
  return static_cast<double>(count) / seconds * 1e-6;
}

void print_throughput(const std::vector<SceneResult>& scenes) {
  std::printf(
      "| scene | primitives | rays | hit | clrt Mrays/s | Embree Mrays/s | clrt/Embree | agree "
      "|\n");
  std::printf("|---|---|---|---:|---:|---:|---:|---:|\n");
  for (const SceneResult& s : scenes) {
    if (!s.skipped.empty())
      std::printf("| %s | %s | skipped: %s | | | | | |\n", s.name.c_str(), s.primitives.c_str(),
                  s.skipped.c_str());
    for (const Measurement& m : s.sets) {
      const double ours = mrays(m.count, m.clrt_seconds), theirs = mrays(m.count, m.embree_seconds);
      std::printf("| %s | %s | %s %s | %.0f%% | %.2f | %.2f | %.2f | %.3f%% |\n", s.name.c_str(),
                  s.primitives.c_str(), m.rays.c_str(),
                  short_count(static_cast<double>(m.count)).c_str(), 100 * m.hit_share, ours,
                  theirs, ours / theirs, 100 * m.agreement);
    }
  }
}

void print_build_times(const std::vector<SceneResult>& scenes) {
  std::printf("\n| scene | clrt build s | Embree build s |\n|---|---:|---:|\n");
  for (const SceneResult& s : scenes)
    if (s.skipped.empty())
      std::printf("| %s | %.3f | %.3f |\n", s.name.c_str(), s.clrt_build_seconds,
                  s.embree_build_seconds);
}

}  // namespace

void print_report(const std::vector<SceneResult>& scenes) {
  print_throughput(scenes);
  print_build_times(scenes);
}

}  // namespace clrt::compare
