#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_loaders.hpp"

namespace clrt {

std::string read_scene_file(const std::string& path) {
  const auto cannot_read = [&](const std::string& why) {
    return SceneError({path, 1, 1}, "cannot read the scene file (" + why + ")");
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw cannot_read("it is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw cannot_read(std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw cannot_read("read error");
  return text.str();
}

}  // namespace clrt
