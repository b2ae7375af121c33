#include "uv_sphere.hpp"

#include <cmath>

namespace clrt::scenes {

TriangleMesh uv_sphere(int rings, int segments,
                       const std::function<double(double theta, double phi)>& radius) {
  TriangleMesh mesh;
  for (int r = 0; r <= rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * M_PI * s / segments;
      const Vec3 p{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
      mesh.positions.push_back(radius ? p * radius(theta, phi) : p);
    }
  }
  const auto vertex = [&](int r, int s) { return static_cast<std::uint32_t>(r * segments + s % segments); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s)
      for (std::uint32_t v : {vertex(r, s), vertex(r, s + 1), vertex(r + 1, s), vertex(r, s + 1),
                              vertex(r + 1, s + 1), vertex(r + 1, s)})
        mesh.corners.push_back(v);
  return mesh;
}

}  // namespace clrt::scenes
