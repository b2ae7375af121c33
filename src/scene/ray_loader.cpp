#include <filesystem>

#include "scene/camera_check.hpp"
#include "scene/command_table.hpp"
#include "scene/coordinate_check.hpp"
#include "scene/lexer.hpp"
#include "scene/limits.hpp"
#include "scene/scene_loaders.hpp"
#include "text/nearest_name.hpp"

namespace clrt {
namespace {

// "unknown command 'sphree' (did you mean 'sphere'?)", the suggestion only when a command is
// close (text/nearest_name.hpp).
SceneError unknown_command(const CommandArgs& args) {
  std::vector<std::string> names;
  for (const auto& [name, handler] : command_table()) names.push_back(name);
  const std::string message = "unknown command '" + excerpt(args.command_word().text) + "'";
  return SceneError(args.command_location(), message + in_parentheses(did_you_mean(args.name(), names)));
}

void apply(LoaderState& state, const CommandArgs& args) {
  const auto command = command_table().find(args.name());
  if (command == command_table().end() || args.command_word().quoted) throw unknown_command(args);
  command->second(state, args);
}

}  // namespace

Scene load_ray_scene(const std::string& path, const FileSource& files) {
  LoaderState state;
  state.files = &files;
  state.scene.path = path;
  state.scene_folder = std::filesystem::path(path).parent_path().string();
  state.scene.materials.push_back(MaterialSpec{});
  const std::string text = read_scene_file(files, path);
  state.text_bytes = text.size();
  std::size_t commands = 0;
  for_each_line(text, path, [&](Line& line) {
    const CommandArgs args(path, line);
    apply(state, args);
    if (++commands % kMemoryCheckCommands == 0 || args.name() == "mesh")
      check_loader_memory(state, args.command_location());
  });
  check_camera(state);
  check_coordinates(state);
  return std::move(state.scene);
}

}  // namespace clrt
