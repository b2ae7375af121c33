#include "scene/polygon_triangulation.hpp"

#include <iterator>
#include <list>
#include <string>

#include "scene/limits.hpp"

namespace clrt {
namespace {

// Newell's normal: the polygon's area vector, well defined even when some corners are straight.
Vec3 polygon_normal(const std::vector<Vec3>& v) {
  Vec3 n;
  for (std::size_t i = 0; i < v.size(); ++i) n = n + cross(v[i], v[(i + 1) % v.size()]);
  return n;
}

// How the corner at b turns, seen along `normal`: > 0 counter-clockwise (convex), < 0 reflex.
double turn(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
  return dot(cross(b - a, c - b), normal);
}

bool is_convex(const std::vector<Vec3>& v, const Vec3& normal) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (turn(v[(i + n - 1) % n], v[i], v[(i + 1) % n], normal) < 0) return false;
  return true;
}

bool has_area(const std::vector<Vec3>& v, const TriangleCorners& t) {
  return cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]) != Vec3{0, 0, 0};
}

// Whether p lies in the triangle abc or on its border, seen along `normal`.
bool inside(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
  return turn(a, b, p, normal) >= 0 && turn(b, c, p, normal) >= 0 && turn(c, a, p, normal) >= 0;
}

using Ring = std::list<std::size_t>;

Ring::const_iterator next_in(const Ring& ring, Ring::const_iterator it) {
  return ++it == ring.end() ? ring.begin() : it;
}

Ring::const_iterator previous_in(const Ring& ring, Ring::const_iterator it) {
  return it == ring.begin() ? std::prev(ring.end()) : std::prev(it);
}

// What the ear test found for a corner; a value >= 0 is a witness: a vertex inside the corner's
// triangle, so the corner is no ear while that vertex and the corner's neighbours stay.
constexpr long kEar = -3;
constexpr long kUnknown = -2;  // not tested since its neighbours or its witness changed
constexpr long kReflex = -1;   // turns clockwise (or not at all): no ear while its neighbours stay

// A corner that turns counter-clockwise and holds no other vertex can be cut off.
long ear_test(const std::vector<Vec3>& v, const Ring& ring, Ring::const_iterator corner,
              const Vec3& normal) {
  const std::size_t a = *previous_in(ring, corner), b = *corner, c = *next_in(ring, corner);
  if (turn(v[a], v[b], v[c], normal) <= 0) return kReflex;
  for (std::size_t other : ring)
    if (other != a && other != b && other != c && v[other] != v[a] && v[other] != v[b] &&
        v[other] != v[c] && inside(v[other], v[a], v[b], v[c], normal))
      return static_cast<long>(other);
  return kEar;
}

// Cuts the first ear in the ring's order, again and again. What each corner's last test found
// is kept, and only corners whose triangle changed (the neighbours of a cut) or whose witness was
// cut are tested again: about one test per corner in all, not one per corner and cut.
std::vector<TriangleCorners> clip_ears(const std::vector<Vec3>& v, const Vec3& normal) {
  Ring ring;
  for (std::size_t i = 0; i < v.size(); ++i) ring.push_back(i);
  std::vector<long> status(v.size(), kUnknown);
  std::vector<std::vector<std::size_t>> witnessed(v.size());  // corners each vertex blocks
  std::vector<TriangleCorners> triangles;
  while (ring.size() > 3) {
    auto corner = ring.cbegin();
    for (; corner != ring.cend(); ++corner) {
      if (status[*corner] != kUnknown) continue;
      const long found = ear_test(v, ring, corner, normal);
      if (found == kEar) break;
      status[*corner] = found;
      if (found >= 0) witnessed[static_cast<std::size_t>(found)].push_back(*corner);
    }
    // No ear: the polygon crosses itself or has lost its area; a fan covers what remains.
    if (corner == ring.cend()) break;
    const std::size_t before = *previous_in(ring, corner), after = *next_in(ring, corner);
    triangles.push_back({before, *corner, after});
    status[before] = status[after] = kUnknown;
    for (std::size_t blocked : witnessed[*corner])
      if (status[blocked] == static_cast<long>(*corner)) status[blocked] = kUnknown;
    ring.erase(corner);
  }
  const std::size_t first = ring.front();
  for (auto it = std::next(ring.cbegin()); std::next(it) != ring.cend(); ++it)
    triangles.push_back({first, *it, *std::next(it)});
  return triangles;
}

}  // namespace

ConcavePolygonTooLarge::ConcavePolygonTooLarge(std::size_t corners)
    : std::runtime_error("a concave polygon of " + std::to_string(corners) +
                         " corners: clrt cuts concave polygons of at most " +
                         std::to_string(limits::kMaxConcavePolygonCorners) +
                         " corners (convex ones of any size)") {}

std::vector<TriangleCorners> triangulate_polygon(const std::vector<Vec3>& vertices) {
  const Vec3 normal = polygon_normal(vertices);
  std::vector<TriangleCorners> all;
  if (is_convex(vertices, normal)) {
    for (std::size_t i = 1; i + 1 < vertices.size(); ++i) all.push_back({0, i, i + 1});
  } else {
    if (vertices.size() > limits::kMaxConcavePolygonCorners)
      throw ConcavePolygonTooLarge(vertices.size());
    all = clip_ears(vertices, normal);
  }
  std::vector<TriangleCorners> kept;
  for (const TriangleCorners& t : all)
    if (has_area(vertices, t)) kept.push_back(t);
  return kept;
}

}  // namespace clrt
