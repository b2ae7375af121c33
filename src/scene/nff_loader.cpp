// Reads Eric Haines' Neutral File Format (the SPD benchmark scenes) into the same Scene as .ray.
#include "scene/camera_check.hpp"
#include "scene/coordinate_check.hpp"
#include "scene/nff_entities.hpp"
#include "scene/nff_state.hpp"
#include "scene/scene_loaders.hpp"

namespace clrt {
namespace {

const NffTable& nff_table() {
  static const NffTable table = [] {
    NffTable t;
    add_nff_view_entities(t);
    add_nff_look_entities(t);
    add_nff_shape_entities(t);
    add_nff_polygon_entities(t);
    return t;
  }();
  return table;
}

void apply(NffState& state, const CommandArgs& args) {
  advance_view(state, args);
  const auto handler = nff_table().find(args.name());
  if (handler == nff_table().end() || args.command_word().quoted)
    throw SceneError(args.command_location(), "unknown entity '" + args.command_word().text +
                                                  "' (NFF has v, b, l, f, c, s, p and pp)");
  handler->second(state, args);
}

}  // namespace

Scene load_nff_scene(const std::string& path, const FileSource& files) {
  NffState state;
  state.loader.files = &files;
  Scene& scene = state.loader.scene;
  scene.path = path;
  // SPD traces ray trees 5 deep counting the eye ray as the first; clrt counts it as depth 0.
  scene.max_depth = 4;
  scene.materials.push_back(MaterialSpec{});
  const std::string text = read_scene_file(files, path);
  state.loader.text_bytes = text.size();
  std::size_t count = 0;
  NffEntityGrouper entities(path, [&](const Line& entity) {
    const CommandArgs args(path, entity);
    apply(state, args);
    if (++count % kMemoryCheckCommands == 0) check_loader_memory(state.loader, args.command_location());
  });
  // Just past the file's last word, where "the file ends too soon" errors point.
  SourceLocation end{path, 1, 1};
  for_each_line(text, path, [&](Line& line) {
    end = {path, line.words.back().line, line.words.back().end_column};
    entities.take(line);
  });
  entities.finish();
  finish_view(state, end);
  finish_lights(state);
  check_camera(state.loader);
  check_coordinates(state.loader);
  return std::move(state.loader.scene);
}

}  // namespace clrt
