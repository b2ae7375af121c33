// Polygons into triangles: fans for convex ones, ear clipping for concave ones.
#include "scene/polygon_triangulation.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "scene/limits.hpp"

using clrt::TriangleCorners;
using clrt::triangulate_polygon;
using clrt::Vec3;

namespace {

using Triangles = std::vector<TriangleCorners>;

double area(const std::vector<Vec3>& v, const TriangleCorners& t, const Vec3& up) {
  return dot(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]), up) / 2;
}

// The shoelace area of a polygon in the plane z = 0.
double polygon_area(const std::vector<Vec3>& v) {
  double twice = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 &a = v[i], &b = v[(i + 1) % v.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice / 2;
}

// A star of `points` tips (radius 1) and notches (radius 0.6) in z = 0, counter-clockwise.
std::vector<Vec3> star(int points) {
  std::vector<Vec3> v;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 2 * points; ++i) {
    const double r = i % 2 == 0 ? 1 : 0.6, a = pi * i / points;
    v.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  return v;
}

}  // namespace

TEST_CASE("a triangle is itself, unless it has no area", "[scene][polygons]") {
  CHECK(triangulate_polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) == Triangles{{0, 1, 2}});
  CHECK(triangulate_polygon({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).empty());
  CHECK(triangulate_polygon({{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}).empty());
}

TEST_CASE("a convex polygon is a fan from its first vertex", "[scene][polygons]") {
  const std::vector<Vec3> pentagon{{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}};
  CHECK(triangulate_polygon(pentagon) == Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
  // Clockwise (seen from +z) is as convex: the fan keeps the polygon's own direction.
  const std::vector<Vec3> clockwise{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  CHECK(triangulate_polygon(clockwise) == Triangles{{0, 1, 2}, {0, 2, 3}});
}

TEST_CASE("a straight corner gives a triangle without area, which is left out",
          "[scene][polygons]") {
  const std::vector<Vec3> square{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  CHECK(triangulate_polygon(square) == Triangles{{0, 2, 3}, {0, 3, 4}});
}

TEST_CASE("a concave polygon loses its first ear each time", "[scene][polygons]") {
  // An L: the corner at (1, 1) is reflex. (5, 0, 1) is no ear while (1, 1) lies on its long
  // side; (0, 1, 2) is the first ear, then (0, 2, 3), then (5, 0, 3), leaving (3, 4, 5).
  const std::vector<Vec3> l{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  CHECK(triangulate_polygon(l) == Triangles{{0, 1, 2}, {0, 2, 3}, {5, 0, 3}, {3, 4, 5}});
}

TEST_CASE("ear clipping covers a star exactly, every triangle facing the polygon's way",
          "[scene][polygons]") {
  for (bool reversed : {false, true}) {
    std::vector<Vec3> v = star(40);
    if (reversed) std::reverse(v.begin(), v.end());
    const Vec3 up{0, 0, reversed ? -1.0 : 1.0};
    const Triangles triangles = triangulate_polygon(v);
    CHECK(triangles.size() == v.size() - 2);
    double sum = 0;
    for (const TriangleCorners& t : triangles) {
      CHECK(area(v, t, up) > 0);
      sum += area(v, t, up);
    }
    CHECK(sum == Approx(std::abs(polygon_area(v))).epsilon(1e-12));
  }
}

TEST_CASE("a polygon that crosses itself still ends, with at most n - 2 triangles",
          "[scene][polygons]") {
  const std::vector<Vec3> bow_tie{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}, {1, 3, 0}};
  CHECK(triangulate_polygon(bow_tie).size() <= 3);
}

namespace {

// `corners` points on the unit circle, counter-clockwise: convex however many there are.
std::vector<Vec3> circle(int corners) {
  std::vector<Vec3> v;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < corners; ++i)
    v.push_back({std::cos(2 * pi * i / corners), std::sin(2 * pi * i / corners), 0});
  return v;
}

}  // namespace

TEST_CASE("a convex polygon of 200k corners is cut into its fan, covering it exactly",
          "[scene][polygons]") {
  const std::vector<Vec3> v = circle(200000);
  const Triangles triangles = triangulate_polygon(v);
  REQUIRE(triangles.size() == v.size() - 2);
  double sum = 0;
  bool all_counter_clockwise = true;
  for (const TriangleCorners& t : triangles) {
    all_counter_clockwise = all_counter_clockwise && area(v, t, {0, 0, 1}) > 0;
    sum += area(v, t, {0, 0, 1});
  }
  CHECK(all_counter_clockwise);
  CHECK(sum == Approx(polygon_area(v)).epsilon(1e-9));
}

TEST_CASE("a concave polygon is cut up to the corner limit and refused beyond it, at once",
          "[scene][polygons][errors]") {
  const std::size_t limit = clrt::limits::kMaxConcavePolygonCorners;
  const std::vector<Vec3> at_limit = star(static_cast<int>(limit / 2));
  REQUIRE(at_limit.size() == limit);
  const Triangles triangles = triangulate_polygon(at_limit);
  CHECK(triangles.size() == limit - 2);
  double sum = 0;
  for (const TriangleCorners& t : triangles) sum += area(at_limit, t, {0, 0, 1});
  CHECK(sum == Approx(polygon_area(at_limit)).epsilon(1e-9));

  CHECK_THROWS_WITH(triangulate_polygon(star(100000)),
                    "a concave polygon of 200000 corners: clrt cuts concave polygons of at most " +
                        std::to_string(limit) + " corners (convex ones of any size)");
}
