#include "compare_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <utility>

#include "agreement.hpp"
#include "clrt_tracer.hpp"
#include "embree_scene.hpp"
#include "geometry/geometry_data.hpp"
#include "host_rays.hpp"
#include "host_threads.hpp"
#include "scene_summary.hpp"

namespace clrt::compare {
namespace {

std::string describe(const HostRay& r, const std::string& answers) {
  char text[160];
  std::snprintf(text, sizeof text,
                "o (%.9g, %.9g, %.9g) d (%.9g, %.9g, %.9g) tmax %g: ", r.origin[0], r.origin[1],
                r.origin[2], r.dir[0], r.dir[1], r.dir[2], r.tmax);
  return text + answers;
}

std::string closest_answers(const dev::Hit& hit, float embree_t) {
  char text[96];
  std::snprintf(text, sizeof text, "clrt t %.9g (instance %u), Embree t %.9g",
                hit.instance == CLRT_NO_HIT ? INFINITY : hit.geometric_normal.w, hit.instance,
                embree_t);
  return text;
}

double share(std::size_t part, std::size_t whole) {
  return whole ? static_cast<double>(part) / static_cast<double>(whole) : 0;
}

struct BestSeconds {
  double clrt = INFINITY, embree = INFINITY;
};

// One untimed round (PoCL compiles a kernel's work-group function at its first launch for a
// grid size), then `runs` rounds that alternate the tracers, so that a busy spell of the
// shared machine slows both alike; the fastest round of each counts.
BestSeconds time_alternating(ClrtTracer& clrt, ClrtBatch& batch, const CompareOptions& options,
                             const std::function<void(std::size_t, std::size_t)>& embree_range) {
  BestSeconds best;
  for (int run = 0; run <= options.runs; ++run) {
    const double ours = clrt.launch(batch);
    const double theirs =
        parallel_seconds(batch.count, options.threads, [&](std::size_t b, std::size_t e) {
          flush_denormals();
          embree_range(b, e);
        });
    if (run == 0) continue;
    best.clrt = std::min(best.clrt, ours);
    best.embree = std::min(best.embree, theirs);
  }
  return best;
}

Measurement closest_hits(ClrtTracer& clrt, const EmbreeScene& embree, const RaySet& set,
                         const CompareOptions& options,
                         std::vector<dev::Hit>* clrt_hits = nullptr) {
  ClrtBatch batch = clrt.closest_batch(set);
  std::vector<float> theirs(set.rays.size());
  const BestSeconds best =
      time_alternating(clrt, batch, options, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) theirs[i] = embree.closest_t(set.rays[i]);
      });
  std::vector<dev::Hit> ours = clrt.hits(batch);
  const Agreement agreement = closest_agreement(set, ours, theirs);
  Measurement m{set.name, set.rays.size(), hit_share(ours), best.clrt, best.embree, agreement.share,
                {}};
  for (std::size_t i : agreement.examples)
    m.disagreements.push_back(describe(set.rays[i], closest_answers(ours[i], theirs[i])));
  if (clrt_hits) *clrt_hits = std::move(ours);
  return m;
}

Measurement occlusion(ClrtTracer& clrt, const EmbreeScene& embree, const RaySet& set,
                      const CompareOptions& options) {
  ClrtBatch batch = clrt.occlusion_batch(set);
  std::vector<char> theirs(set.rays.size());
  const BestSeconds best =
      time_alternating(clrt, batch, options, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) theirs[i] = embree.occluded(set.rays[i]);
      });
  const std::vector<char> ours = clrt.blocked(batch);
  const Agreement agreement = occlusion_agreement(ours, theirs);
  const auto blocked = static_cast<std::size_t>(std::count(ours.begin(), ours.end(), 1));
  Measurement m{set.name,  set.rays.size(), share(blocked, set.rays.size()),
                best.clrt, best.embree,     agreement.share,
                {}};
  for (std::size_t i : agreement.examples)
    m.disagreements.push_back(describe(
        set.rays[i], ours[i] ? "clrt blocked, Embree clear" : "clrt clear, Embree blocked"));
  return m;
}

void record(SceneResult& result, Measurement m) {
  std::fprintf(stderr, "  %-7s %9zu rays, %5.1f%% hit: clrt %.4f s, Embree %.4f s, agree %.3f%%\n",
               m.rays.c_str(), m.count, 100 * m.hit_share, m.clrt_seconds, m.embree_seconds,
               100 * m.agreement);
  for (const std::string& ray : m.disagreements)
    std::fprintf(stderr, "    disagree: %s\n", ray.c_str());
  result.sets.push_back(std::move(m));
}

}  // namespace

SceneResult compare_scene(const std::string& path, DeviceContext& device,
                          const compute::program& program, const CompareOptions& options) {
  SceneResult result;
  result.name = std::filesystem::path(path).stem().string();
  std::fprintf(stderr, "%s: loading\n", path.c_str());
  const Scene scene = load_scene(path);
  result.primitives = primitive_label(scene);
  result.skipped = unsupported_shapes(scene);
  if (!result.skipped.empty()) {
    std::fprintf(stderr, "  skipped: Embree gets no %s here\n", result.skipped.c_str());
    return result;
  }
  GeometryData geometry = build_geometry(scene);
  result.clrt_build_seconds = geometry.build_seconds;
  ClrtTracer clrt(device, program, std::move(geometry));
  const EmbreeScene embree(scene, options.threads, options.quality, options.flags);
  result.embree_build_seconds = embree.build_seconds();
  std::fprintf(stderr, "  %s; build: clrt %.3f s, Embree %.3f s\n", result.primitives.c_str(),
               result.clrt_build_seconds, result.embree_build_seconds);

  const RaySet camera = camera_rays(scene);
  std::vector<dev::Hit> camera_hits;
  record(result, closest_hits(clrt, embree, camera, options, &camera_hits));
  record(result,
         closest_hits(clrt, embree, random_rays(embree.bounds(), options.random_rays, 1), options));
  const RaySet shadows = shadow_rays(scene, camera, camera_hits);
  if (!shadows.rays.empty()) record(result, occlusion(clrt, embree, shadows, options));
  return result;
}

}  // namespace clrt::compare
