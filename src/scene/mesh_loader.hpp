// Reads a Wavefront OBJ file into a MeshData.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/file_source.hpp"
#include "scene/memory_limit.hpp"
#include "scene/mtl_reader.hpp"
#include "scene/scene.hpp"
#include "scene/source_location.hpp"

namespace clrt {

// A mesh file that cannot be used; what() names the file, and the line and column when the
// problem has a place in it, but not the scene command that asked for the file: the caller adds
// that location.
class MeshError : public std::runtime_error {
 public:
  MeshError(const std::string& path, const std::string& message);  // "PATH: MESSAGE"
  MeshError(const SourceLocation& where, const std::string& message);  // "PATH:LINE:COLUMN: MESSAGE"
};

// A malformed MTL library of a mesh: the caller names it as a material library, not a mesh file.
class MaterialLibraryError : public MeshError {
 public:
  using MeshError::MeshError;
};

// Polygons are cut into fans. Vertex normals are kept only if every corner of every face has
// one; texture coordinates for the triangles whose three corners name one (MeshData::texcoords).
// Throws MeshError for a file that cannot be read, a malformed line (a word that is not a
// finite single-precision number, a wrong number of them, a bad face corner), an index out of
// range, or a mesh with no triangles. A large file is parsed in slices on every core; the result
// and the error reported do not depend on how many.
// The file comes from `files` (the disk unless the scene's files came from elsewhere).
// Loading stops with a MeshError, before the memory is spent, at the line where the file and the
// tables parsed so far pass `memory`, or before the tables are gathered into the mesh when the
// slices' tables and the mesh's side by side would (this error's line depends on the slices).
MeshData load_obj_mesh(const std::string& path, const FileSource& files = disk_files(),
                       const MemoryLimit& memory = {});

// The materials of a mesh's `usemtl` names (MeshData::material_names), read from its `mtllib`
// libraries (found beside the OBJ file) and mapped onto clrt's model (scene/mtl_material.hpp):
// none for a name no library defines. A library that cannot be read, a name no library
// defines and what a library says that clrt does not render are warnings, each said once; a
// malformed library is a MaterialLibraryError.
struct MeshMaterials {
  std::vector<std::optional<MaterialSpec>> by_name;
  // Per name, the maps clrt renders (map_Kd, map_Ks), their paths resolved against their
  // library's folder; for the scene's loader to read as textures.
  std::vector<std::optional<MtlTextureRef>> color_maps, specular_maps;
  std::vector<std::string> warnings;  // "FILE:LINE:COLUMN: warning: ..."
};
MeshMaterials load_mesh_materials(const MeshData& mesh, const FileSource& files = disk_files());

}  // namespace clrt
