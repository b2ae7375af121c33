// How far the two tracers' answers agree: a speed comparison of tracers that disagree is
// worthless.
#pragma once

#include <vector>

#include "host_rays.hpp"
#include "shared/ray.h"

namespace clrt::compare {

// Tolerance on t: relative to t, but never below kOriginTolerance times the origin's largest
// coordinate. Near t = 0 the float rounding of the origin alone (about 6e-8 of it, times a
// small factor per operation) outweighs a relative bound, and rays drawn inside the scene's
// box start that close to a surface.
constexpr double kTTolerance = 1e-3;
constexpr double kOriginTolerance = 1e-5;

struct Agreement {
  double share = 1;                   // of the rays on which the tracers agree
  std::vector<std::size_t> examples;  // the first few rays on which they do not
};

// Agreeing: both miss, or both hit at t within the tolerance above. `embree_t` is INFINITY on
// a miss.
Agreement closest_agreement(const RaySet& set, const std::vector<dev::Hit>& clrt_hits,
                            const std::vector<float>& embree_t);

// Agreeing: both call the ray blocked, or both call it clear.
Agreement occlusion_agreement(const std::vector<char>& clrt_blocked,
                              const std::vector<char>& embree_blocked);

// The share of clrt's hits among its answers.
double hit_share(const std::vector<dev::Hit>& clrt_hits);

}  // namespace clrt::compare
