#include "scene/input_text.hpp"
#include "scene/limits.hpp"
#include "scene/scene_loaders.hpp"

namespace clrt {

std::string read_scene_file(const std::string& path) {
  try {
    return read_input_text(path, limits::kMaxSceneFileBytes);
  } catch (const InputFileError& e) {
    throw SceneError({path, 1, 1}, std::string("cannot read the scene file (") + e.what() + ")");
  }
}

}  // namespace clrt
