#include "image/input_file_checks.hpp"
#include "scene/limits.hpp"
#include "scene/scene_loaders.hpp"
#include "scene/scene_text_check.hpp"

namespace clrt {

std::string read_scene_file(const FileSource& files, const std::string& path) {
  try {
    std::string text(without_byte_order_mark(files.open(path, limits::kMaxSceneFileBytes)->text()));
    check_scene_is_text(path, text);
    return text;
  } catch (const FileChangedError& e) {
    throw SceneError(SourceLocation::whole_file(path), e.what());
  } catch (const InputFileError& e) {
    throw SceneError(SourceLocation::whole_file(path),
                     std::string("cannot read the scene file (") + e.what() + ")");
  }
}

}  // namespace clrt
