// The output must never replace an input: writing renames a finished temporary over the path,
// which would destroy the scene (`clrt s.png` writes s.png by default) or one of its meshes.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace clrt {

// Throws ImageError if `output` names the same file as the scene or any mesh it loaded (also
// through another spelling, a link or a hard link).
void check_output_is_not_input(const std::string& output, const Scene& scene);

}  // namespace clrt
