#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/camera_check.hpp"
#include "scene/command_table.hpp"
#include "scene/lexer.hpp"

namespace clrt {
namespace {

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

void apply(LoaderState& state, const Line& line) {
  const CommandArgs args(state.scene.path, line);
  const auto command = command_table().find(args.name());
  if (command == command_table().end() || line.words.front().quoted)
    throw SceneError(args.command_location(), "unknown command '" + line.words.front().text + "'");
  command->second(state, args);
}

}  // namespace

Scene load_scene(const std::string& path) {
  LoaderState state;
  state.scene.path = path;
  state.scene_folder = std::filesystem::path(path).parent_path().string();
  state.scene.materials.push_back(MaterialSpec{});
  for (const Line& line : split_into_lines(read_scene_file(path), path)) apply(state, line);
  check_camera(state);
  return std::move(state.scene);
}

}  // namespace clrt
