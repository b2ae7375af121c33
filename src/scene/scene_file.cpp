#include "scene/input_file_checks.hpp"
#include "scene/limits.hpp"
#include "scene/scene_loaders.hpp"

namespace clrt {

std::string read_scene_file(const FileSource& files, const std::string& path) {
  try {
    return std::string(without_byte_order_mark(files.open(path, limits::kMaxSceneFileBytes)->text()));
  } catch (const FileChangedError& e) {
    throw SceneError({path, 1, 1}, e.what());
  } catch (const InputFileError& e) {
    throw SceneError({path, 1, 1}, std::string("cannot read the scene file (") + e.what() + ")");
  }
}

}  // namespace clrt
