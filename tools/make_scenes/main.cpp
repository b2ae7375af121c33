// clrt-make-scenes OUTDIR [--scale S] [--family large|knob|texture-knob]: writes the large
// benchmark scenes, the material knob or the texture knob (README.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "cli/decimal_number.hpp"
#include "cli/tool_command_line.hpp"
#include "knob_scenes.hpp"
#include "large_scenes.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Writes clrt's large procedural benchmark scenes and their meshes, or the material knob.",
               "clrt-make-scenes"};
  clrt::identify_tool(
      app, {"docs/performance.md",
            {},
            {{"0", "the scenes were written (their paths are printed)"},
             {"1", "a file could not be written"},
             {"2", "a usage error"}},
            {{"clrt-make-scenes", "the large benchmark scenes, into build/scenes-large"},
             {"clrt-make-scenes knobs --family knob", "the material knob's scenes, into knobs/"}}});
  std::string folder = "build/scenes-large";
  double scale = 1;
  app.add_option("OUTDIR", folder, "folder to write into (created if missing)")
      ->capture_default_str();
  std::string family = "large";
  app.add_option("--scale", scale, "multiplies every sphere, triangle and instance count")
      ->check(clrt::positive_decimal_number())
      ->capture_default_str();
  app.add_option("--family", family,
                 "large: the large scenes; knob: 1 to 16 materials of rising shading cost; "
                 "texture-knob: 1 to 8 materials of rising texture cost")
      ->check(CLI::IsMember({"large", "knob", "texture-knob"}))
      ->capture_default_str();
  if (const auto status = clrt::parse_tool_arguments(app, argc, argv)) return *status;
  try {
    const auto paths = family == "knob"           ? clrt::scenes::write_knob_scenes(folder, scale)
                       : family == "texture-knob" ? clrt::scenes::write_texture_knob_scenes(folder, scale)
                                                  : clrt::scenes::write_large_scenes(folder, scale);
    for (const std::string& path : paths)
      std::printf("%s\n", path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clrt-make-scenes: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
