// Triangle meshes as the device's Mesh records and per-triangle tables, written in the order of
// each mesh's BVH leaves straight from the scene: no table of the triangles themselves is kept
// (the BVH's leaf packets carry their vertices).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/bvh_box.hpp"
#include "scene/scene.hpp"
#include "shared/scene.h"

namespace clrt {

struct GeometryData;

// What a device mesh's triangles are read from: a mesh file's MeshData (in its object space), or
// the scene's loose `triangle`s (already in world space, each with its own material). Refers to
// them: they must outlive it.
class TriangleSource {
 public:
  // Throws std::invalid_argument for a corner count that is not a multiple of 3 or a corner
  // index out of range.
  explicit TriangleSource(const MeshData& mesh);
  explicit TriangleSource(const std::vector<TriangleSpec>& loose);

  std::size_t size() const { return size_; }
  bool has_normals() const { return has_normals_; }

  // Triangle t's vertices in single precision, as the device tests them.
  dev::Triangle triangle(std::size_t t) const;
  // The mesh's vertex normals as unit vectors in single precision, zero where one cannot be
  // normalised (empty without normals), on every core: a vertex normal is shared by several
  // triangles, so it is normalised once rather than at each of its corners.
  std::vector<std::array<float, 3>> unit_normals() const;
  // Triangle t's unit vertex normals, read from `unit` (unit_normals()); a corner whose normal
  // could not be normalised gets the face normal. Only for a source that has_normals().
  dev::TriangleNormals normals(std::size_t t, const std::vector<std::array<float, 3>>& unit) const;
  // Whether it holds the scene's loose triangles.
  bool loose() const { return loose_ != nullptr; }
  // Whether its triangles have materials of their own: the loose triangles, and a mesh file's
  // faces under a `usemtl` that its libraries define.
  bool has_materials() const { return has_materials_; }
  // Triangle t's own material, or CLRT_INSTANCE_MATERIAL where it takes its instance's.
  dev::u32 material(std::size_t t) const;
  // Whether any of its triangles has texture coordinates of its own (a loose triangle's `uv`,
  // a mesh file's `vt`).
  bool has_texcoords() const { return has_texcoords_; }
  // Triangle t's corners' (u, v): its own, or (0, 0), (1, 0), (0, 1).
  dev::TriangleTexcoords texcoords(std::size_t t) const;

 private:
  const MeshData* mesh_ = nullptr;
  const std::vector<TriangleSpec>* loose_ = nullptr;
  std::size_t size_ = 0;
  bool has_normals_ = false;
  bool has_materials_ = false;
  bool has_texcoords_ = false;
};

// The boxes of the source's triangles (of their single-precision vertices), on every core.
std::vector<Box> triangle_boxes(const TriangleSource& source);

// The device record of a mesh whose triangles start at `first_triangle` of the per-triangle
// tables (its BVH root is set later).
dev::Mesh device_mesh(const TriangleSource& source, dev::u32 first_triangle);

// Writes the per-triangle rows of `mesh` (its device record, rows placed) for source triangle
// order[i], on every core: triangle_source at mesh.first_triangle + i, and where the source has
// them, normals at mesh.normals + i, materials at material_rows + i and texture coordinates at
// mesh.texcoords + i. The tables must already hold those rows.
void write_triangle_rows(const TriangleSource& source, const std::vector<std::uint32_t>& order,
                         const dev::Mesh& mesh, dev::u32 material_rows, GeometryData& out);

}  // namespace clrt
