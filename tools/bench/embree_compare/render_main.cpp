// clrt-embree-render SCENE.ray -o OUT [--resolution WxH] [--threads T]: the scene rendered by a
// Whitted tracer on Embree 3 (whitted_tracer.hpp), the yardstick for clrt's whole command
// (README.md, "The whole command").
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "cli/tool_command_line.hpp"
#include "cli/whole_number.hpp"
#include "embree_scene.hpp"
#include "math/number_fields.hpp"
#include "whitted_tracer.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Renders a .ray scene with a Whitted tracer on Embree 3, for timing clrt against it.",
               "clrt-embree-render"};
  clrt::identify_tool(app);
  std::string scene_path, output;
  std::optional<std::vector<std::uint64_t>> size;  // --resolution's width and height
  int threads = 2;
  app.add_option("SCENE", scene_path, ".ray scene")->required();
  app.add_option("-o,--output", output, "image file (its extension names the format)")->required();
  app.add_option_function<std::string>(
      "--resolution",
      [&size](const std::string& text) {
        size = clrt::read_number_fields(text, {"#x#", 6, false, true});
        if (!size || (*size)[0] == 0 || (*size)[1] == 0)
          throw CLI::ValidationError("--resolution", "takes WIDTHxHEIGHT, e.g. 1280x720");
      },
      "image size WxH (default: the scene's)");
  app.add_option("--threads", threads, "host threads for Embree's build and the tracing")
      ->transform(clrt::whole_number(1, 4096))
      ->capture_default_str();
  if (const auto status = clrt::parse_tool_arguments(app, argc, argv)) return *status;
  clrt::Scene scene;
  try {
    scene = clrt::load_scene(scene_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clrt-embree-render: error: %s\n", e.what());
    return 2;
  }
  std::string unsupported = clrt::compare::unsupported_shapes(scene);
  const std::string lights = clrt::compare::unsupported_lights(scene);
  if (!lights.empty()) unsupported += (unsupported.empty() ? "" : ", ") + lights;
  if (!unsupported.empty()) {
    std::fprintf(stderr, "clrt-embree-render: error: %s: this tracer cannot render %s\n", scene_path.c_str(),
                 unsupported.c_str());
    return 2;
  }
  clrt::RenderOptions options = clrt::RenderOptions::from_scene(scene);
  if (size) {
    options.width = static_cast<int>((*size)[0]);
    options.height = static_cast<int>((*size)[1]);
  }
  try {
    const clrt::compare::EmbreeScene embree(scene, threads, RTC_BUILD_QUALITY_HIGH, RTC_SCENE_FLAG_NONE);
    clrt::write_image(output, clrt::compare::render_whitted(scene, embree, options, threads));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clrt-embree-render: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
