#include "geometry/emitter_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include "geometry/instance_bounds.hpp"
#include "math/cumulative_shares.hpp"
#include "scene/device_vector.hpp"

namespace clrt {
namespace {

struct TableBuilder {
  std::vector<dev::Emitter>& rows;
  std::vector<double> power;  // per row: luminance times area

  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& radiance) {
    const double area = 0.5 * length(cross(b - a, c - a));
    if (!(area > 0)) return;  // a degenerate triangle is never hit
    dev::Emitter e{};
    e.origin = f4_of(a);
    e.edge1 = f4_of(b - a);
    e.edge2 = f4_of(c - a);
    e.radiance = f4_of(radiance);
    rows.push_back(e);
    power.push_back(glow_luminance(radiance) * area);
  }

  // The triangle (a, b, c), counter-clockwise in object space, placed by m: mirrored when m
  // turns space inside out, so that its corners' order still points its normal to the front
  // the device's (M^-1)^T gives it.
  void placed_triangle(const Mat4& m, bool mirrors, const Vec3& a, const Vec3& b, const Vec3& c,
                       const Vec3& radiance) {
    const Vec3 wa = m.transform_point(a), wb = m.transform_point(b), wc = m.transform_point(c);
    if (mirrors) triangle(wa, wc, wb, radiance);
    else triangle(wa, wb, wc, radiance);
  }
};

// The cube [-1, 1]^3's faces, two counter-clockwise triangles each seen from outside.
void cube(TableBuilder& table, const Mat4& m, bool mirrors, const Vec3& radiance) {
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {-1.0, 1.0}) {
      Vec3 n, u, v;
      double* nn = axis == 0 ? &n.x : axis == 1 ? &n.y : &n.z;
      *nn = side;
      // u x v = n: the next two axes in cyclic order, v's sign following the face's side.
      const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
      (ua == 0 ? u.x : ua == 1 ? u.y : u.z) = 1;
      (va == 0 ? v.x : va == 1 ? v.y : v.z) = side;
      const Vec3 c00 = n - u - v, c10 = n + u - v, c11 = n + u + v, c01 = n - u + v;
      table.placed_triangle(m, mirrors, c00, c10, c11, radiance);
      table.placed_triangle(m, mirrors, c00, c11, c01, radiance);
    }
  }
}

Vec3 vertex(const dev::f4& v) { return {v.x, v.y, v.z}; }

// A material's emission; none for an index past the table (scenes built in code may have no
// materials).
Vec3 emission_of(const Scene& scene, int material) {
  const auto m = static_cast<std::size_t>(material);
  return m < scene.materials.size() ? scene.materials[m].emission : Vec3{};
}

// A mesh instance's glowing triangles.
void mesh(TableBuilder& table, const Scene& scene, const InstanceSpec& spec, const TriangleSource& source) {
  const Mat4& m = spec.transform;
  const bool mirrors = m.determinant() < 0;
  const MeshData& data = scene.meshes.at(static_cast<std::size_t>(spec.mesh));
  for (std::size_t t = 0; t < source.size(); ++t) {
    const Vec3 radiance = emission_of(scene, mesh_triangle_material(spec, data, t));
    if (!(glow_luminance(radiance) > 0)) continue;
    const dev::Triangle tri = source.triangle(t);
    table.placed_triangle(m, mirrors, vertex(tri.v0), vertex(tri.v1), vertex(tri.v2), radiance);
  }
}

// Whether any of the mesh instance's faces glows.
bool mesh_glows(const Scene& scene, const InstanceSpec& spec) {
  if (glow_luminance(emission_of(scene, spec.material)) > 0) return true;
  if (!spec.mesh_materials) return false;
  const MeshData& mesh = scene.meshes[static_cast<std::size_t>(spec.mesh)];
  return std::any_of(mesh.name_materials.begin(), mesh.name_materials.end(),
                     [&](int m) { return m >= 0 && glow_luminance(emission_of(scene, m)) > 0; });
}

}  // namespace

double glow_luminance(const Vec3& r) { return 0.2126 * r.x + 0.7152 * r.y + 0.0722 * r.z; }

bool glow_is_sampled(const Scene& scene) {
  for (const TriangleSpec& t : scene.triangles)
    if (glow_luminance(emission_of(scene, t.material)) > 0) return true;
  for (const InstanceSpec& spec : scene.instances) {
    if (spec.motion >= 0) continue;
    if (spec.shape == ShapeKind::Mesh && mesh_glows(scene, spec)) return true;
    if (!(glow_luminance(emission_of(scene, spec.material)) > 0)) continue;
    if (spec.shape == ShapeKind::Cube || world_sphere(spec)) return true;
  }
  return false;
}

void build_emitter_table(const Scene& scene, const std::vector<TriangleSource>& sources,
                         GeometryData& out) {
  TableBuilder table{out.emitters, {}};
  for (std::size_t i = 0; i < out.instances.size(); ++i) {
    dev::Instance& inst = out.instances[i];
    inst.glow = CLRT_NO_GLOW;
    const std::size_t before = table.rows.size();
    if (out.instance_source[i] < 0) {  // the loose triangles, each with its own material
      const TriangleSource& source = sources[inst.mesh];
      for (std::size_t t = 0; t < source.size(); ++t) {
        const TriangleSpec& spec = scene.triangles[t];
        const Vec3 radiance = emission_of(scene, spec.material);
        if (glow_luminance(radiance) > 0) table.triangle(spec.v0, spec.v1, spec.v2, radiance);
      }
      if (table.rows.size() > before) inst.glow = CLRT_GLOW_TRIANGLES;
      continue;
    }
    const InstanceSpec& spec = scene.instances[static_cast<std::size_t>(out.instance_source[i])];
    // A moving surface has no one place to sample: paths that hit it take its light in full.
    if (spec.motion >= 0) continue;
    if (spec.shape == ShapeKind::Mesh) {
      mesh(table, scene, spec, sources[inst.mesh]);
      if (table.rows.size() > before) inst.glow = CLRT_GLOW_TRIANGLES;
      continue;
    }
    const Vec3 radiance = emission_of(scene, spec.material);
    if (!(glow_luminance(radiance) > 0)) continue;
    const Mat4& m = spec.transform;
    const bool mirrors = m.determinant() < 0;
    switch (spec.shape) {
      case ShapeKind::Sphere: {
        const std::optional<WorldSphere> sphere = world_sphere(spec);
        if (!sphere) break;
        const double r = sphere->radius;
        dev::Emitter e{};
        e.origin = f4_of(sphere->center);
        e.edge1.w = static_cast<float>(r);
        e.radiance = f4_of(radiance);
        inst.glow = static_cast<dev::u32>(table.rows.size());
        table.rows.push_back(e);
        table.power.push_back(glow_luminance(radiance) * 4 * M_PI * r * r);
        break;
      }
      case ShapeKind::Cube:
        cube(table, m, mirrors, radiance);
        if (table.rows.size() > before) inst.glow = CLRT_GLOW_TRIANGLES;
        break;
      case ShapeKind::Mesh:  // above
      case ShapeKind::Plane:
      case ShapeKind::Cylinder:
      case ShapeKind::Cone:
        break;
    }
  }
  if (table.rows.size() >= CLRT_GLOW_TRIANGLES)
    throw std::length_error("the scene has more than 2^32 - 3 glowing triangles and spheres");
  double total = 0;
  for (double p : table.power) total += p;
  out.emitter_power = total;
  const std::vector<float> shares = cumulative_shares(table.power);
  for (std::size_t r = 0; r < table.rows.size(); ++r) table.rows[r].origin.w = shares[r];
}

}  // namespace clrt
