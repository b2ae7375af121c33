// Whether two loaded Scenes describe the same picture: what the NFF loader gives against the
// .ray file converted from the same NFF file.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace clrt::test {

// The first difference found, in words, or "" when there is none. Numbers agree when they
// differ by at most `tolerance` times the larger of 1 and their size. Materials are compared by
// value (not index); spheres, cubes, cones, cylinders and planes in order; triangles as one
// unordered set in world space, whether loose or in a mesh, each up to a rotation of its corners,
// with its vertex normals when it has them.
std::string scene_difference(const Scene& a, const Scene& b, double tolerance);

}  // namespace clrt::test
