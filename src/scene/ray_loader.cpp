#include <filesystem>

#include "scene/camera_check.hpp"
#include "scene/command_table.hpp"
#include "scene/coordinate_check.hpp"
#include "scene/lexer.hpp"
#include "scene/limits.hpp"
#include "scene/scene_loaders.hpp"

namespace clrt {
namespace {

void apply(LoaderState& state, const Line& line) {
  const CommandArgs args(state.scene.path, line);
  const auto command = command_table().find(args.name());
  if (command == command_table().end() || line.words.front().quoted)
    throw SceneError(args.command_location(),
                     "unknown command '" + excerpt(line.words.front().text) + "'");
  command->second(state, args);
}

}  // namespace

Scene load_ray_scene(const std::string& path, const FileSource& files) {
  LoaderState state;
  state.files = &files;
  state.scene.path = path;
  state.scene_folder = std::filesystem::path(path).parent_path().string();
  state.scene.materials.push_back(MaterialSpec{});
  for (const Line& line : split_into_lines(read_scene_file(files, path), path)) apply(state, line);
  check_camera(state);
  check_coordinates(state);
  return std::move(state.scene);
}

}  // namespace clrt
