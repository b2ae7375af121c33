// The megakernel and the wavefront give the same bits on every scene in the repository's
// scenes/ (kernels/accumulate.cl writes down the order both follow), with several samples, in
// cast and path modes, and with a wavefront small enough that waves are split. The megakernel refuses a
// ray tree deeper than its stack before any work.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "device/device_select.hpp"
#include "render/renderer.hpp"
#include "render/usage_error.hpp"
#include "render_support.hpp"
#include "render/integrator_names.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

struct Variant {
  const char* what;
  std::function<void(RenderOptions&)> adjust;
};

const std::vector<Variant> kVariants = {
    {"the scene's settings", [](RenderOptions&) {}},
    {"3 samples per pixel, seed 5",
     [](RenderOptions& o) {
       o.samples = 3;
       o.seed = 5;
     }},
    {"cast mode", [](RenderOptions& o) { o.mode = RenderMode::Cast; }},
    {"a 1024-ray wavefront", [](RenderOptions& o) { o.wavefront = 1024; }},
    {"path mode, 4 samples per pixel",
     [](RenderOptions& o) {
       o.mode = RenderMode::Path;
       o.samples = 4;
     }},
    {"shading class by class", [](RenderOptions& o) { o.shade_by_class = true; }},
    {"path mode, shading class by class",
     [](RenderOptions& o) {
       o.mode = RenderMode::Path;
       o.samples = 2;
       o.shade_by_class = true;
     }},
    {"path mode, a 1024-ray wavefront, seed 9",
     [](RenderOptions& o) {
       o.mode = RenderMode::Path;
       o.samples = 2;
       o.wavefront = 1024;
       o.seed = 9;
     }},
};

}  // namespace

TEST_CASE("every integrator gives the product's bits on every repository scene",
          "[integrators]") {
  const std::vector<std::string> scenes = repository_scenes();
  const std::vector<std::string> integrators = integrator_names();
  REQUIRE(scenes.size() >= 17);
  REQUIRE(integrators.size() >= 2);
  for (const std::string& path : scenes) {
    for (const Variant& v : kVariants) {
      const auto with = [&](const std::string& kind) {
        return [&, kind](RenderOptions& o) {
          o.width = 48;
          o.height = 32;
          v.adjust(o);
          o.integrator = kind;
        };
      };
      const FloatImage product = render_file(path, with(integrators.front()));
      for (std::size_t i = 1; i < integrators.size(); ++i) {
        INFO(path << ", " << v.what << ", " << integrators[i]);
        CHECK(same_bits(product, render_file(path, with(integrators[i]))));
      }
    }
  }
}

TEST_CASE("the megakernel refuses a maximum depth its stack cannot hold", "[integrators]") {
  const Scene scene = load_scene(test_scene("reflect.ray"));
  RenderSetup setup;
  setup.options = RenderOptions::from_scene(scene);
  setup.options.integrator = "megakernel";
  setup.options.max_depth = 33;  // the CPU class's stack holds 32
  setup.devices = select_devices("cpu");
  CHECK_THROWS_AS(check_render_setup(setup), UsageError);
  RenderStats stats;
  CHECK_THROWS_WITH(render(scene, setup, stats), Catch::Contains("--integrator wavefront"));
  setup.options.max_depth = 32;
  CHECK_NOTHROW(check_render_setup(setup));
  setup.options.integrator = "wavefront";
  setup.options.max_depth = 1000;
  CHECK_NOTHROW(check_render_setup(setup));
}
