#include "geometry/mesh_table.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "geometry/geometry_data.hpp"
#include "math/parallel_for.hpp"
#include "math/to_float.hpp"

namespace clrt {
namespace {

constexpr std::size_t kChunk = 32768;  // triangles per task of a parallel loop: small meshes take one

dev::f4 to_f4(const Vec3& v) { return {to_float(v.x), to_float(v.y), to_float(v.z), 0.0f}; }

std::array<float, 3> to_floats(const Vec3& v) { return {to_float(v.x), to_float(v.y), to_float(v.z)}; }

// A unit vector has a component of at least 1/sqrt(3), so only unit_or_zero's zero is all zeros
// in single precision.
bool all_zero(const std::array<float, 3>& v) { return v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f; }

void check_indices(const std::vector<std::uint32_t>& corners, std::size_t count, const MeshData& mesh) {
  for (std::uint32_t index : corners)
    if (index >= count)
      throw std::invalid_argument("mesh " + mesh.path + ": corner index " + std::to_string(index) + " out of range");
}

}  // namespace

TriangleSource::TriangleSource(const MeshData& mesh) : mesh_(&mesh), size_(mesh.corners.size() / 3) {
  if (mesh.corners.size() % 3 != 0)
    throw std::invalid_argument("mesh " + mesh.path + ": corner count is not a multiple of 3");
  has_normals_ = !mesh.normals.empty() && mesh.corner_normals.size() == mesh.corners.size();
  if (!mesh.triangle_names.empty() && mesh.triangle_names.size() != size_)
    throw std::invalid_argument("mesh " + mesh.path + ": material names for " +
                                std::to_string(mesh.triangle_names.size()) + " of " + std::to_string(size_) +
                                " triangles");
  has_materials_ = !mesh.triangle_names.empty() &&
                   std::any_of(mesh.name_materials.begin(), mesh.name_materials.end(), [](int m) { return m >= 0; });
  check_indices(mesh.corners, mesh.positions.size(), mesh);
  if (has_normals_) check_indices(mesh.corner_normals, mesh.normals.size(), mesh);
  has_texcoords_ = !mesh.corner_texcoords.empty();
  if (has_texcoords_) {
    if (mesh.corner_texcoords.size() != mesh.corners.size())
      throw std::invalid_argument("mesh " + mesh.path + ": texture coordinates for some corners only");
    for (std::uint32_t index : mesh.corner_texcoords)
      if (index != kNoMeshTexcoord && index >= mesh.texcoords.size())
        throw std::invalid_argument("mesh " + mesh.path + ": texture coordinate index " + std::to_string(index) +
                                    " out of range");
  }
}

TriangleSource::TriangleSource(const std::vector<TriangleSpec>& loose)
    : loose_(&loose), size_(loose.size()), has_materials_(true),
      has_texcoords_(std::any_of(loose.begin(), loose.end(), [](const TriangleSpec& t) { return t.has_uv; })) {}

dev::Triangle TriangleSource::triangle(std::size_t t) const {
  if (loose_) {
    const TriangleSpec& s = (*loose_)[t];
    return {to_f4(s.v0), to_f4(s.v1), to_f4(s.v2)};
  }
  const std::uint32_t* c = &mesh_->corners[3 * t];
  return {to_f4(mesh_->positions[c[0]]), to_f4(mesh_->positions[c[1]]), to_f4(mesh_->positions[c[2]])};
}

std::vector<std::array<float, 3>> TriangleSource::unit_normals() const {
  if (!has_normals_) return {};
  std::vector<std::array<float, 3>> unit(mesh_->normals.size());
  parallel_for(unit.size(), kChunk, [&](std::size_t i) { unit[i] = to_floats(unit_or_zero(mesh_->normals[i])); });
  return unit;
}

// A vertex normal that cannot be normalised is replaced by the face normal, so that every
// triangle of a mesh with normals interpolates valid unit vectors.
dev::TriangleNormals TriangleSource::normals(std::size_t t, const std::vector<std::array<float, 3>>& unit) const {
  const std::uint32_t* c = &mesh_->corners[3 * t];
  const std::uint32_t* n = &mesh_->corner_normals[3 * t];
  dev::TriangleNormals out{};
  for (int k = 0; k < 3; ++k) {
    std::array<float, 3> v = unit[n[k]];
    if (all_zero(v)) {
      const Vec3& p0 = mesh_->positions[c[0]];
      v = to_floats(unit_or_zero(cross(mesh_->positions[c[1]] - p0, mesh_->positions[c[2]] - p0)));
    }
    for (int a = 0; a < 3; ++a) out.n[3 * k + a] = v[a];
  }
  return out;
}

dev::u32 TriangleSource::material(std::size_t t) const {
  if (loose_) return static_cast<dev::u32>((*loose_)[t].material);
  const int own = mesh_face_material(*mesh_, t);
  return own < 0 ? CLRT_INSTANCE_MATERIAL : static_cast<dev::u32>(own);
}

dev::TriangleTexcoords TriangleSource::texcoords(std::size_t t) const {
  dev::TriangleTexcoords out{{0, 0, 1, 0, 0, 1}};
  if (loose_) {
    for (int k = 0; k < 6; ++k) out.uv[k] = (*loose_)[t].uv[static_cast<std::size_t>(k)];
  } else if (has_texcoords_ && mesh_->corner_texcoords[3 * t] != kNoMeshTexcoord) {
    for (int k = 0; k < 3; ++k) {
      const std::array<float, 2>& uv = mesh_->texcoords[mesh_->corner_texcoords[3 * t + static_cast<std::size_t>(k)]];
      out.uv[2 * k] = uv[0];
      out.uv[2 * k + 1] = uv[1];
    }
  }
  return out;
}

std::vector<Box> triangle_boxes(const TriangleSource& source) {
  std::vector<Box> boxes(source.size());
  parallel_for(source.size(), kChunk, [&](std::size_t t) {
    const dev::Triangle tri = source.triangle(t);
    for (const dev::f4& v : {tri.v0, tri.v1, tri.v2}) boxes[t].grow(v.x, v.y, v.z);
  });
  return boxes;
}

dev::Mesh device_mesh(const TriangleSource& source, dev::u32 first_triangle) {
  dev::Mesh mesh{};
  mesh.first_triangle = first_triangle;
  mesh.triangle_count = static_cast<dev::u32>(source.size());
  mesh.normals = CLRT_NO_NORMALS;  // its rows, as its texture coordinates', are placed with the
  mesh.texcoords = CLRT_NO_TEXCOORDS;  // other meshes'
  return mesh;
}

void write_triangle_rows(const TriangleSource& source, const std::vector<std::uint32_t>& order,
                         const dev::Mesh& mesh, dev::u32 material_rows, GeometryData& out) {
  const std::vector<std::array<float, 3>> unit = source.unit_normals();
  parallel_for(order.size(), kChunk, [&](std::size_t i) {
    const std::uint32_t t = order[i];
    if (source.has_normals()) out.triangle_normals[mesh.normals + i] = source.normals(t, unit);
    if (source.has_materials()) out.triangle_materials[material_rows + i] = source.material(t);
    if (source.has_texcoords()) out.triangle_texcoords[mesh.texcoords + i] = source.texcoords(t);
    out.triangle_source[mesh.first_triangle + i] = t;
  });
}

}  // namespace clrt
