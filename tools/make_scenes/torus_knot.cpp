#include "torus_knot.hpp"

#include <algorithm>
#include <cmath>

namespace clrt::scenes {
namespace {

// Knot (p, q) = (2, 3) on a torus of radii kMajor and kMinor, tube radius kTube: the bounds
// in the header are kMajor + kMinor + kTube across and kMinor + kTube up.
constexpr int kP = 2, kQ = 3;
constexpr double kMajor = 2.0, kMinor = 0.8, kTube = 0.35;

Vec3 knot_point(double theta) {
  const double rho = kMajor + kMinor * std::cos(kQ * theta);
  return {rho * std::cos(kP * theta), kMinor * std::sin(kQ * theta), rho * std::sin(kP * theta)};
}

// The Frenet frame from central differences: the knot's curvature never vanishes, so the
// principal normal is defined everywhere and the frame closes up after one turn.
struct Frame {
  Vec3 centre, normal, binormal;
};

Frame knot_frame(double theta) {
  constexpr double h = 1e-4;
  const Vec3 before = knot_point(theta - h), centre = knot_point(theta),
             after = knot_point(theta + h);
  const Vec3 tangent = normalize(after - before);
  const Vec3 bend = after - centre * 2.0 + before;
  const Vec3 normal = normalize(bend - tangent * dot(bend, tangent));
  return {centre, normal, cross(tangent, normal)};
}

}  // namespace

KnotGrid knot_grid_for(long long triangles) {
  KnotGrid grid;
  grid.around = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 16.0))));
  grid.along = std::max(3, static_cast<int>(std::lround(triangles / (2.0 * grid.around))));
  return grid;
}

TriangleMesh torus_knot(const KnotGrid& grid) {
  constexpr double kTwoPi = 6.283185307179586;
  TriangleMesh mesh;
  for (int i = 0; i < grid.along; ++i) {
    const Frame f = knot_frame(kTwoPi * i / grid.along);
    for (int j = 0; j < grid.around; ++j) {
      const double phi = kTwoPi * j / grid.around;
      const Vec3 n = f.normal * std::cos(phi) + f.binormal * std::sin(phi);
      mesh.positions.push_back(f.centre + n * kTube);
      mesh.normals.push_back(n);
    }
  }
  const auto vertex = [&grid](int i, int j) {
    return static_cast<std::uint32_t>((i % grid.along) * grid.around + j % grid.around);
  };
  // Around the tube, then along the knot: cross(d/dphi, d/dtheta) points out of the tube.
  for (int i = 0; i < grid.along; ++i)
    for (int j = 0; j < grid.around; ++j) {
      const std::uint32_t a = vertex(i, j), b = vertex(i, j + 1), c = vertex(i + 1, j),
                          d = vertex(i + 1, j + 1);
      mesh.corners.insert(mesh.corners.end(), {a, b, c, b, d, c});
    }
  return mesh;
}

}  // namespace clrt::scenes
