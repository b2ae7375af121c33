#include <fstream>
#include <iterator>

#include "fuzz_paths.hpp"
#include "fuzz_require.hpp"
#include "scene/polygon_triangulation.hpp"

namespace clrt::fuzz {
namespace {

// Checking that a polygon is simple takes a test per pair of edges.
constexpr std::size_t kMostCheckedCorners = 512;

// Twice the area of abc in the plane z = 0, exact for the small whole coordinates used here.
double cross_z(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

int side(const Vec3& a, const Vec3& b, const Vec3& p) {
  const double turn = cross_z(a, b, p);
  return (turn > 0) - (turn < 0);
}

bool on_segment(const Vec3& a, const Vec3& b, const Vec3& p) {
  return side(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Whether segments ab and cd share a point.
bool touch(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) ||
         on_segment(c, d, b);
}

// Flat, and no edge meets another except its neighbours at their shared corner; no corner is
// straight (a straight corner's neighbours would touch along the edge).
bool simple_and_flat(const std::vector<Vec3>& v) {
  const std::size_t n = v.size();
  for (const Vec3& p : v)
    if (p.z != 0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (side(v[i], v[(i + 1) % n], v[(i + 2) % n]) == 0) return false;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (touch(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])) return false;
    }
  }
  return true;
}

}  // namespace

Outcome polygon(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // The first byte: even, the corners lie in the plane z = 0, 2 bytes each (x, y); odd, 3 (x, y,
  // z).
  const std::size_t stride = !bytes.empty() && bytes[0] % 2 ? 3 : 2;
  const auto coordinate = [&](std::size_t at) {
    return static_cast<double>(static_cast<signed char>(bytes[at]));
  };
  std::vector<Vec3> corners;
  for (std::size_t i = 1; i + stride <= bytes.size(); i += stride)
    corners.push_back({coordinate(i), coordinate(i + 1), stride == 3 ? coordinate(i + 2) : 0.0});
  if (corners.size() < 3) return Outcome::Rejected;
  std::vector<TriangleCorners> triangles;
  try {
    triangles = triangulate_polygon(corners);
  } catch (const ConcavePolygonTooLarge&) {
    return Outcome::Rejected;
  }
  require(triangles.size() <= corners.size() - 2, "more triangles than corners less two");
  for (const TriangleCorners& t : triangles) {
    for (std::size_t corner : t) require(corner < corners.size(), "a triangle past the corners");
    require(cross(corners[t[1]] - corners[t[0]], corners[t[2]] - corners[t[0]]) != Vec3{0, 0, 0},
            "a triangle without area");
  }
  if (corners.size() <= kMostCheckedCorners && simple_and_flat(corners)) {
    double polygon_area = 0;
    for (std::size_t i = 0; i < corners.size(); ++i)
      polygon_area += cross_z({0, 0, 0}, corners[i], corners[(i + 1) % corners.size()]);
    double triangle_area = 0;
    for (const TriangleCorners& t : triangles) {
      const double area = cross_z(corners[t[0]], corners[t[1]], corners[t[2]]);
      require(area * polygon_area > 0, "a triangle of a simple polygon faces the other way");
      triangle_area += area;
    }
    require(triangle_area == polygon_area, "a simple polygon's triangles do not add up to it");
  }
  return Outcome::Accepted;
}

}  // namespace clrt::fuzz
