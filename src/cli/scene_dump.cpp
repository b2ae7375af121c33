#include "cli/scene_dump.hpp"

#include <iostream>

#include "cli/out_of_memory.hpp"
#include "image/byte_sink.hpp"
#include "image/output_target.hpp"
#include "render/output_guard.hpp"
#include "render/usage_error.hpp"
#include "scene/scene_json.hpp"

namespace clrt {

int dump_scene(const CliOptions& cli) {
  const std::string& path = *cli.dump_scene;
  const bool to_stdout = path == kStdoutPath;
  try {
    if (!to_stdout) check_output_writable(path);
  } catch (const ImageError& e) {
    throw UsageError(e.what());
  }
  Scene scene;
  try {
    scene = naming_out_of_memory("loading " + cli.scene, [&] { return load_scene(cli.scene); });
  } catch (const SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  // The settings the command line overrides are dumped as clrt would render them.
  const RenderOptions render = resolve_render_options(cli, scene);
  scene.width = render.width;
  scene.height = render.height;
  scene.samples = render.samples;
  scene.max_depth = render.max_depth;
  try {
    if (!to_stdout) check_output_is_not_input(path, scene);
  } catch (const ImageError& e) {
    throw UsageError(e.what());
  }
  const std::unique_ptr<image_detail::ByteSink> sink = image_detail::open_output_sink(path);
  write_scene_json(scene, [&](const std::string& piece) { sink->write(piece.data(), piece.size()); });
  sink->finish();
  return 0;
}

}  // namespace clrt
