#include "geometry/mesh_table.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace clrt {
namespace {

dev::f4 to_f4(const Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

Vec3 unit_or_zero(const Vec3& v) {
  const double len = length(v);
  return len > 0 ? v / len : Vec3{};
}

// A vertex normal that cannot be normalised is replaced by the face normal, so that every
// triangle of a mesh with normals interpolates valid unit vectors.
std::array<Vec3, 3> corner_normals(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& n) {
  const Vec3 face = unit_or_zero(cross(p[1] - p[0], p[2] - p[0]));
  std::array<Vec3, 3> out;
  for (int k = 0; k < 3; ++k) {
    const Vec3 unit = unit_or_zero(n[k]);
    out[k] = unit == Vec3{} ? face : unit;
  }
  return out;
}

void append_triangle(GeometryData& out, const std::array<Vec3, 3>& p,
                     const std::array<Vec3, 3>* normals, dev::u32 material, dev::u32 source) {
  out.triangles.push_back({to_f4(p[0]), to_f4(p[1]), to_f4(p[2])});
  dev::TriangleNormals n{};
  if (normals) {
    const std::array<Vec3, 3> unit = corner_normals(p, *normals);
    n = {to_f4(unit[0]), to_f4(unit[1]), to_f4(unit[2])};
  }
  out.triangle_normals.push_back(n);
  out.triangle_materials.push_back(material);
  out.triangle_source.push_back(source);
}

dev::Mesh begin_mesh(const GeometryData& out, std::size_t triangle_count, bool has_normals) {
  dev::Mesh mesh{};
  mesh.first_triangle = static_cast<dev::u32>(out.triangles.size());
  mesh.triangle_count = static_cast<dev::u32>(triangle_count);
  mesh.has_normals = has_normals ? 1u : 0u;
  return mesh;
}

template <class V>
const V& at(const std::vector<V>& table, std::uint32_t index, const MeshData& mesh) {
  if (index >= table.size())
    throw std::invalid_argument("mesh " + mesh.path + ": corner index " + std::to_string(index) +
                                " out of range");
  return table[index];
}

}  // namespace

void append_mesh(const MeshData& mesh, GeometryData& out) {
  if (mesh.corners.size() % 3 != 0)
    throw std::invalid_argument("mesh " + mesh.path + ": corner count is not a multiple of 3");
  const bool has_normals = !mesh.normals.empty() && mesh.corner_normals.size() == mesh.corners.size();
  const std::size_t count = mesh.corners.size() / 3;
  out.meshes.push_back(begin_mesh(out, count, has_normals));
  for (std::size_t t = 0; t < count; ++t) {
    std::array<Vec3, 3> p, n;
    for (int k = 0; k < 3; ++k) {
      p[k] = at(mesh.positions, mesh.corners[3 * t + k], mesh);
      if (has_normals) n[k] = at(mesh.normals, mesh.corner_normals[3 * t + k], mesh);
    }
    append_triangle(out, p, has_normals ? &n : nullptr, 0, static_cast<dev::u32>(t));
  }
}

void append_loose_triangles(const std::vector<TriangleSpec>& triangles, GeometryData& out) {
  out.meshes.push_back(begin_mesh(out, triangles.size(), false));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const TriangleSpec& tri = triangles[t];
    append_triangle(out, {tri.v0, tri.v1, tri.v2}, nullptr, static_cast<dev::u32>(tri.material),
                    static_cast<dev::u32>(t));
  }
}

}  // namespace clrt
