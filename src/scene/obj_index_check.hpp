// Checks the face indices of OBJ text before tinyobjloader sees it: tinyobjloader only warns
// about indices past the end (or silently drops such faces), and gives no useful line for them.
#pragma once

#include <string>

namespace clrt {

// Throws MeshError naming `path` and the line of the first face with a zero or out-of-range
// position or normal index, or with fewer than three corners.
void check_obj_face_indices(const std::string& text, const std::string& path);

}  // namespace clrt
