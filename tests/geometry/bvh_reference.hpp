// The nearest hit of a ray with a whole Scene, by brute force in double precision, independent
// of the kernels: every object is tested, canonical shapes in their object space through
// M^-1 computed on the host, triangles in world space (Moller-Trumbore). A ray is flagged
// ambiguous when a float implementation may rightly disagree: it grazes an object (the object
// grown and shrunk by a relative 1e-5 about its centre give different answers), two objects
// are hit at nearly the same t, or the hit lies next to tmin or tmax.
#pragma once

#include <limits>

#include "scene/scene.hpp"

namespace clrt::bvhtest {

// What was hit, named in the Scene's own terms.
struct ObjectId {
  int instance = -1;  // index in Scene::instances; -1 for a loose `triangle`
  int triangle = -1;  // triangle within the MeshData, or index in Scene::triangles; -1 for shapes
  bool operator==(const ObjectId& o) const { return instance == o.instance && triangle == o.triangle; }
};

struct ReferenceResult {
  bool hit = false;
  double t = std::numeric_limits<double>::infinity();
  ObjectId object;
  bool ambiguous = false;
};

// The nearest hit with tmin < t < tmax.
ReferenceResult reference_closest_hit(const Scene& scene, const Vec3& o, const Vec3& d,
                                      double tmin, double tmax);

// The tolerance on t that comparisons with single-precision results use.
double t_tolerance(double t);

}  // namespace clrt::bvhtest
