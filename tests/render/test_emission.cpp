// Glowing surfaces (`emission`) as every mode and integrator shows them: the front side sends its
// radiance to the camera exactly, the back side nothing (docs/scene-format.md#materials).
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "render/integrator_names.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

// A black, glowing `object` filling the middle of a 16 x 16 view, no lights, black background.
std::string glowing(const ScratchDir& dir, const std::string& object) {
  const std::string path = dir.file("glow.ray");
  std::ofstream(path) << "eye 0 0 4\nlookat 0 0 0\nfov 40\nresolution 16 16\nbackground 0 0 0\n"
                         "material 0 0 0 0 0 0 1 0 0\nemission 0.25 0.5 0.75\n"
                      << object << "\n";
  return path;
}

float channel_at(const FloatImage& image, int x, int y, int c) {
  return image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x) + c];
}

}  // namespace

TEST_CASE("a glowing surface shows its emission from the front and nothing from behind",
          "[render][emission]") {
  const ScratchDir dir;
  struct Case {
    const char* what;
    std::string object;
    float scale;  // 1: its front faces the camera
  };
  const Case cases[] = {{"a sphere", "sphere 0 0 0 1", 1},
                        {"a triangle facing the camera", "triangle -5 -5 0 5 -5 0 0 5 0", 1},
                        {"a triangle facing away", "triangle -5 -5 0 0 5 0 5 -5 0", 0}};
  for (const Case& c : cases) {
    const std::string path = glowing(dir, c.object);
    for (const RenderMode mode : {RenderMode::Cast, RenderMode::Trace, RenderMode::Path}) {
      for (const std::string& integrator : integrator_names()) {
        const FloatImage image = render_file(path, [&](RenderOptions& o) {
          o.mode = mode;
          o.samples = 4;
          o.integrator = integrator;
        });
        INFO(c.what << ", mode " << static_cast<int>(mode) << ", " << integrator);
        for (const auto& [x, y] : {std::pair{8, 8}, std::pair{7, 7}, std::pair{6, 9}}) {
          CHECK(channel_at(image, x, y, 0) == 0.25f * c.scale);
          CHECK(channel_at(image, x, y, 1) == 0.5f * c.scale);
          CHECK(channel_at(image, x, y, 2) == 0.75f * c.scale);
        }
      }
    }
  }
}
