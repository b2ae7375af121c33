#include "scene/obj_polygons.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "scene/limits.hpp"

namespace clrt {
namespace {

using Triangle = std::array<std::size_t, 3>;  // polygon corners, in the polygon's winding

float squared_distance_f(const Vec3& a, const Vec3& b) {
  const float x = static_cast<float>(b.x) - static_cast<float>(a.x);
  const float y = static_cast<float>(b.y) - static_cast<float>(a.y);
  const float z = static_cast<float>(b.z) - static_cast<float>(a.z);
  return x * x + y * y + z * z;
}

std::vector<Triangle> cut_quad(const std::vector<Vec3>& p) {
  if (squared_distance_f(p[0], p[2]) < squared_distance_f(p[1], p[3])) return {{0, 1, 2}, {0, 2, 3}};
  return {{0, 1, 3}, {1, 2, 3}};
}

// The polygon in the plane that its normal is most nearly perpendicular to.
struct Plane2 {
  std::vector<double> u, v;
  double orientation = 1;  // +1: counter-clockwise in (u, v); -1: clockwise
};

Plane2 project(const std::vector<Vec3>& p) {
  Vec3 n;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  const int drop = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
  const int iu = drop == 0 ? 1 : 0, iv = drop == 2 ? 1 : 2;
  Plane2 plane;
  for (const Vec3& q : p) {
    plane.u.push_back(q[iu]);
    plane.v.push_back(q[iv]);
  }
  // (iu, iv, drop) is a right-handed cycle except when y is dropped.
  const double along = drop == 0 ? n.x : (drop == 1 ? -n.y : n.z);
  plane.orientation = along < 0 ? -1 : 1;
  return plane;
}

double turn(const Plane2& q, std::size_t a, std::size_t b, std::size_t c) {
  return ((q.u[b] - q.u[a]) * (q.v[c] - q.v[b]) - (q.v[b] - q.v[a]) * (q.u[c] - q.u[b])) * q.orientation;
}

// Whether corner p lies inside or on triangle (a, b, c), which turns left.
bool inside(const Plane2& q, std::size_t p, std::size_t a, std::size_t b, std::size_t c) {
  return turn(q, a, b, p) >= 0 && turn(q, b, c, p) >= 0 && turn(q, c, a, p) >= 0;
}

bool is_ear(const Plane2& q, const std::vector<std::size_t>& left, std::size_t k) {
  const std::size_t n = left.size();
  const std::size_t a = left[(k + n - 1) % n], b = left[k], c = left[(k + 1) % n];
  if (turn(q, a, b, c) <= 0) return false;
  for (std::size_t p : left)
    if (p != a && p != b && p != c && inside(q, p, a, b, c)) return false;
  return true;
}

bool is_convex(const Plane2& q) {
  const std::size_t n = q.u.size();
  for (std::size_t i = 0; i < n; ++i)
    if (turn(q, (i + n - 1) % n, i, (i + 1) % n) <= 0) return false;
  return true;
}

std::vector<Triangle> clip_ears(const std::vector<Vec3>& p) {
  const Plane2 q = project(p);
  std::vector<std::size_t> left(p.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = i;
  std::vector<Triangle> out;
  while (left.size() > 3) {
    std::size_t k = 1;  // the fan's next triangle, when no ear is found
    for (std::size_t i = 0; i < left.size(); ++i)
      if (is_ear(q, left, i)) {
        k = i;
        break;
      }
    const std::size_t n = left.size();
    out.push_back({left[(k + n - 1) % n], left[k], left[(k + 1) % n]});
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
  }
  out.push_back({left[0], left[1], left[2]});
  return out;
}

// The polygon's corners from its fan: (0, 1, 2), (0, 2, 3), ...
template <class T>
std::vector<T> fan_corners(const std::vector<T>& table, std::size_t first, std::size_t count) {
  std::vector<T> c{table[first], table[first + 1]};
  for (std::size_t t = 0; t + 2 < count; ++t) c.push_back(table[first + 3 * t + 2]);
  return c;
}

template <class T>
void write_triangles(std::vector<T>& table, std::size_t first, const std::vector<T>& corners,
                     const std::vector<Triangle>& triangles) {
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) table[first + 3 * t + k] = corners[triangles[t][k]];
}

}  // namespace

bool triangulate_polygon(MeshData& mesh, std::size_t first_corner, std::size_t corners) {
  const std::vector<std::uint32_t> position = fan_corners(mesh.corners, first_corner, corners);
  std::vector<Vec3> points;
  for (std::uint32_t i : position) points.push_back(mesh.positions[i]);
  // The mesh holds the fan already, which covers a convex polygon exactly.
  if (corners > limits::kMaxConcavePolygonCorners) return is_convex(project(points));
  const std::vector<Triangle> triangles = corners == 4 ? cut_quad(points) : clip_ears(points);
  for (std::vector<std::uint32_t>* table : {&mesh.corner_normals, &mesh.corner_texcoords})
    if (!table->empty()) write_triangles(*table, first_corner, fan_corners(*table, first_corner, corners), triangles);
  write_triangles(mesh.corners, first_corner, position, triangles);
  return true;
}

}  // namespace clrt
