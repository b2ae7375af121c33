#include "scene_equivalence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>

namespace clrt::test {
namespace {

struct WorldTriangle {
  std::array<Vec3, 3> corners;
  std::array<Vec3, 3> normals;  // when has_normals
  bool has_normals = false;
  const MaterialSpec* material = nullptr;
};

std::string text(const Vec3& v) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return out.str();
}

class Comparer {
 public:
  explicit Comparer(double tolerance) : tolerance_(tolerance) {}

  double slack(double size) const { return tolerance_ * std::max(1.0, std::abs(size)); }
  bool same(double a, double b) const {
    return std::abs(a - b) <= slack(std::max(std::abs(a), std::abs(b)));
  }
  bool same(const Vec3& a, const Vec3& b) const {
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
  }
  bool same(const Mat4& a, const Mat4& b) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (!same(a.m[i][j], b.m[i][j])) return false;
    return true;
  }
  bool same(const MaterialSpec& a, const MaterialSpec& b) const {
    return same(a.color, b.color) && same(a.ka, b.ka) && same(a.kd, b.kd) && same(a.ks, b.ks) &&
           same(a.shininess, b.shininess) && same(a.kr, b.kr) && same(a.kt, b.kt) &&
           same(a.ior, b.ior);
  }
  bool same(const LightSpec& a, const LightSpec& b) const {
    return a.kind == b.kind && same(a.color, b.color) && same(a.position, b.position) &&
           same(a.direction, b.direction) && same(a.edge_u, b.edge_u) && same(a.edge_v, b.edge_v) &&
           same(a.angle_degrees, b.angle_degrees) && same(a.exponent, b.exponent) &&
           a.samples == b.samples;
  }
  // Up to a rotation of the corners (which keeps the winding, so the front side).
  bool same(const WorldTriangle& a, const WorldTriangle& b) const {
    if (a.has_normals != b.has_normals || !same(*a.material, *b.material)) return false;
    for (int r = 0; r < 3; ++r) {
      bool all = true;
      for (int i = 0; i < 3 && all; ++i) {
        const int k = (i + r) % 3;
        all = same(a.corners[i], b.corners[k]) &&
              (!a.has_normals || same(a.normals[i], b.normals[k]));
      }
      if (all) return true;
    }
    return false;
  }

 private:
  double tolerance_;
};

std::vector<WorldTriangle> world_triangles(const Scene& s) {
  std::vector<WorldTriangle> out;
  for (const TriangleSpec& t : s.triangles)
    out.push_back({{t.v0, t.v1, t.v2}, {}, false, &s.materials[t.material]});
  for (const InstanceSpec& instance : s.instances) {
    if (instance.shape != ShapeKind::Mesh) continue;
    const MeshData& mesh = s.meshes[instance.mesh];
    for (std::size_t first = 0; first < mesh.corners.size(); first += 3) {
      WorldTriangle t;
      t.material = &s.materials[instance.material];
      t.has_normals = !mesh.normals.empty();
      for (std::size_t i = 0; i < 3; ++i) {
        t.corners[i] = instance.transform.transform_point(mesh.positions[mesh.corners[first + i]]);
        if (t.has_normals)
          t.normals[i] =
              instance.transform.inverse().transposed().transform_vector(mesh.normals[mesh.corner_normals[first + i]]);
      }
      out.push_back(t);
    }
  }
  return out;
}

double centre_x(const WorldTriangle& t) {
  return (t.corners[0].x + t.corners[1].x + t.corners[2].x) / 3;
}

// Each triangle of `a` is matched with an unused one of `b` whose centre lies near it in x.
std::string triangle_difference(const Scene& a, const Scene& b, const Comparer& c) {
  const std::vector<WorldTriangle> ta = world_triangles(a), tb = world_triangles(b);
  if (ta.size() != tb.size())
    return "triangles: " + std::to_string(ta.size()) + " against " + std::to_string(tb.size());
  std::vector<std::size_t> order(tb.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return centre_x(tb[i]) < centre_x(tb[j]); });
  std::vector<bool> used(tb.size(), false);
  for (const WorldTriangle& t : ta) {
    double size = 0;
    for (const Vec3& p : t.corners) size = std::max(size, std::abs(p.x));
    const double x = centre_x(t), window = 2 * c.slack(size);
    auto it = std::lower_bound(order.begin(), order.end(), x - window,
                               [&](std::size_t i, double v) { return centre_x(tb[i]) < v; });
    for (; it != order.end() && centre_x(tb[*it]) <= x + window; ++it)
      if (!used[*it] && c.same(t, tb[*it])) break;
    if (it == order.end() || centre_x(tb[*it]) > x + window)
      return "no twin for the triangle " + text(t.corners[0]) + " " + text(t.corners[1]) + " " +
             text(t.corners[2]);
    used[*it] = true;
  }
  return "";
}

std::string shape_difference(const Scene& a, const Scene& b, const Comparer& c) {
  std::vector<const InstanceSpec*> sa, sb;
  for (const InstanceSpec& i : a.instances)
    if (i.shape != ShapeKind::Mesh) sa.push_back(&i);
  for (const InstanceSpec& i : b.instances)
    if (i.shape != ShapeKind::Mesh) sb.push_back(&i);
  if (sa.size() != sb.size())
    return "shapes: " + std::to_string(sa.size()) + " against " + std::to_string(sb.size());
  for (std::size_t k = 0; k < sa.size(); ++k) {
    const InstanceSpec &x = *sa[k], &y = *sb[k];
    const std::string which = "shape " + std::to_string(k) + " (line " +
                              std::to_string(x.place.line) + " against " +
                              std::to_string(y.place.line) + "): ";
    if (x.shape != y.shape) return which + "different kinds";
    if (!c.same(a.materials[x.material], b.materials[y.material]))
      return which + "different materials";
    if (!c.same(x.transform, y.transform)) return which + "different transforms";
    if (x.shape == ShapeKind::Cone &&
        (!c.same(x.cone_r0, y.cone_r0) || !c.same(x.cone_r1, y.cone_r1)))
      return which + "different cone radii";
  }
  return "";
}

std::string view_difference(const Scene& a, const Scene& b, const Comparer& c) {
  if (!c.same(a.camera.eye, b.camera.eye))
    return "eye " + text(a.camera.eye) + " against " + text(b.camera.eye);
  if (!c.same(a.camera.lookat, b.camera.lookat)) return "lookat differs";
  if (!c.same(a.camera.up, b.camera.up)) return "up differs";
  if (!c.same(a.camera.fov_degrees, b.camera.fov_degrees))
    return "fov " + std::to_string(a.camera.fov_degrees) + " against " +
           std::to_string(b.camera.fov_degrees);
  if (!c.same(a.background, b.background)) return "background differs";
  if (a.width != b.width || a.height != b.height) return "resolution differs";
  if (a.max_depth != b.max_depth) return "maxdepth differs";
  if (a.samples != b.samples) return "samples differ";
  if (a.lights.size() != b.lights.size()) return "light counts differ";
  for (std::size_t i = 0; i < a.lights.size(); ++i)
    if (!c.same(a.lights[i], b.lights[i])) return "light " + std::to_string(i) + " differs";
  return "";
}

}  // namespace

std::string scene_difference(const Scene& a, const Scene& b, double tolerance) {
  const Comparer c(tolerance);
  for (const std::string& difference :
       {view_difference(a, b, c), shape_difference(a, b, c), triangle_difference(a, b, c)})
    if (!difference.empty()) return difference;
  return "";
}

}  // namespace clrt::test
