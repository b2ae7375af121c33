// The paths each fuzz target drives an input through, shared by the libFuzzer targets and by
// test_fuzz_regressions, which replays every input they found.
#pragma once

#include <string>

namespace clrt::fuzz {

enum class Outcome { Rejected, Accepted };

// Each reads the file at `path` the way clrt does. The reader's own error (SceneError, MeshError,
// ImageError) is Rejected. An accepted input that breaks what its reader promises throws
// std::logic_error; any other exception escapes. Both are findings.

// A .ray scene through the loader, the BVH build and the frame set-up.
Outcome ray_scene(const std::string& path);
// An OBJ mesh through load_obj_mesh().
Outcome obj_mesh(const std::string& path);
// An image through read_image(), which picks the reader by the path's extension.
Outcome image(const std::string& path);

}  // namespace clrt::fuzz
