// Reads a Wavefront OBJ file into a MeshData.
#pragma once

#include <stdexcept>
#include <string>

#include "scene/scene.hpp"

namespace clrt {

// A mesh file that cannot be used; what() names the file (and its line when known) but not the
// scene command that asked for it: the caller adds that location.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Polygons are triangulated. Vertex normals are kept only if every corner of every face has
// one. Throws MeshError for a file that cannot be read, a bad index, or a mesh with no triangles.
MeshData load_obj_mesh(const std::string& path);

}  // namespace clrt
