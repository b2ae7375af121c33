// A UV sphere, optionally displaced: rings x segments quads, two triangles each, counter-clockwise
// seen from outside. The benchmarks' and the BVH tests' small procedural meshes.
#pragma once

#include <functional>

#include "torus_knot.hpp"

namespace clrt::scenes {

// radius(theta, phi) scales the unit sphere's point at polar angle theta and azimuth phi; the
// mesh has no normals.
TriangleMesh uv_sphere(int rings, int segments,
                       const std::function<double(double theta, double phi)>& radius = {});

}  // namespace clrt::scenes
