// The path_render fuzz path: an accepted .ray scene rendered in path mode, which must give a
// finite value in every pixel. Materials and lights are where non-finite samples came from (a
// Phong exponent of 1e9, an area light with parallel edges); the scene's own size, samples and
// depth are cut down so that each input renders in milliseconds.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "fuzz_paths.hpp"
#include "fuzz_require.hpp"
#include "device/device_select.hpp"
#include "render/renderer.hpp"
#include "render/usage_error.hpp"
#include "scene/scene.hpp"
#include "render/integrator_names.hpp"

namespace clrt::fuzz {

Outcome path_render(const std::string& path) {
  Scene scene;
  try {
    scene = load_scene(path);
  } catch (const SceneError&) {
    return Outcome::Rejected;
  }
  const char* spec = std::getenv("CLRT_TEST_DEVICE");
  RenderSetup setup;
  setup.options = RenderOptions::from_scene(scene);
  setup.options.mode = RenderMode::Path;
  setup.options.width = setup.options.height = 6;
  setup.options.samples = 4;
  setup.options.max_depth = std::min(setup.options.max_depth, 4);
  setup.devices = select_devices(spec && *spec ? spec : "cpu");
  for (const std::string& integrator : integrator_names()) {
    setup.options.integrator = integrator;
    RenderStats stats;
    FloatImage image;
    try {
      image = render(scene, setup, stats);
    } catch (const UsageError&) {
      return Outcome::Rejected;  // more than this machine holds: refused before any work
    }
    for (const float v : image.rgb)
      require(std::isfinite(v), "an accepted scene rendered a non-finite value in path mode");
  }
  return Outcome::Accepted;
}

}  // namespace clrt::fuzz
