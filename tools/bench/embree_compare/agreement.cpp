#include "agreement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace clrt::compare {
namespace {

bool same_t(const HostRay& ray, const dev::Hit& hit, float embree_t) {
  const bool clrt_hit = hit.instance != CLRT_NO_HIT, embree_hit = std::isfinite(embree_t);
  if (clrt_hit != embree_hit) return false;
  if (!clrt_hit) return true;
  const double a = hit.geometric_normal.w, b = embree_t;
  const double origin =
      std::max({std::abs(ray.origin[0]), std::abs(ray.origin[1]), std::abs(ray.origin[2])});
  return std::abs(a - b) <=
         std::max(kTTolerance * std::max(std::abs(a), std::abs(b)), kOriginTolerance * origin);
}

constexpr std::size_t kExamples = 3;

void check_counts(std::size_t a, std::size_t b) {
  if (a != b) throw std::logic_error("the two tracers answered different ray counts");
}

// `same(i)` says whether the tracers agree on ray i of `count`.
template <typename Same>
Agreement agreement_where(std::size_t count, Same same) {
  Agreement result;
  if (count == 0) return result;
  std::size_t agreeing = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (same(i))
      ++agreeing;
    else if (result.examples.size() < kExamples)
      result.examples.push_back(i);
  }
  result.share = static_cast<double>(agreeing) / static_cast<double>(count);
  return result;
}

}  // namespace

Agreement closest_agreement(const RaySet& set, const std::vector<dev::Hit>& clrt_hits,
                            const std::vector<float>& embree_t) {
  check_counts(clrt_hits.size(), embree_t.size());
  check_counts(clrt_hits.size(), set.rays.size());
  return agreement_where(clrt_hits.size(), [&](std::size_t i) {
    return same_t(set.rays[i], clrt_hits[i], embree_t[i]);
  });
}

Agreement occlusion_agreement(const std::vector<char>& clrt_blocked,
                              const std::vector<char>& embree_blocked) {
  check_counts(clrt_blocked.size(), embree_blocked.size());
  return agreement_where(clrt_blocked.size(),
                         [&](std::size_t i) { return clrt_blocked[i] == embree_blocked[i]; });
}

double hit_share(const std::vector<dev::Hit>& clrt_hits) {
  if (clrt_hits.empty()) return 0;
  const auto hits = std::count_if(clrt_hits.begin(), clrt_hits.end(),
                                  [](const dev::Hit& h) { return h.instance != CLRT_NO_HIT; });
  return static_cast<double>(hits) / static_cast<double>(clrt_hits.size());
}

}  // namespace clrt::compare
