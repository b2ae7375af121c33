// Runs scene_closest_hit and scene_any_hit (kernels/geometry/scene_intersect.h) on the test
// device over a GeometryData, and maps device hits back to the Scene's objects.
#pragma once

#include <vector>

#include "bvh_reference.hpp"
#include "bvh_test_scenes.hpp"
#include "geometry/geometry_data.hpp"
#include "shared/ray.h"

namespace clrt::bvhtest {

std::vector<dev::Hit> device_closest_hits(const GeometryData& geometry, const std::vector<TestRay>& rays);

// 1 where the ray has a hit with tmin <= t < tmax, else 0.
std::vector<int> device_any_hits(const GeometryData& geometry, const std::vector<TestRay>& rays);

// The Scene object a device hit names, through the build's instance and triangle maps.
ObjectId hit_object(const GeometryData& geometry, const dev::Hit& hit);

}  // namespace clrt::bvhtest
