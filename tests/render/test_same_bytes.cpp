// Every OpenCL implementation renders the same bits as PoCL: each scene of the repository, both
// integrators, at the device's own local size and wavefront and at others. Run on PoCL it holds
// PoCL to its own bits across those settings; CTest's test_same_bytes@intel and @oclgrind run
// it on the other implementations (tests/support/on_implementation.sh).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "render/integrator.hpp"
#include "render_support.hpp"
#include "render/integrator_names.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

struct Setting {
  const char* what;
  std::size_t local_size;
  std::uint32_t wavefront;
};

}  // namespace

TEST_CASE("the test device renders PoCL's bits on every repository scene", "[same-bytes]") {
  // Oclgrind interprets every instruction and checks every access: tiny images, the defaults.
  const bool interpreter = device().device().platform().name() == "Oclgrind";
  const int width = interpreter ? 12 : 64, height = interpreter ? 9 : 48;
  std::vector<Setting> settings = {{"the device's defaults", 0, 0}};
  if (!interpreter) {
    settings.push_back({"local size 16, a 1024-ray wavefront", 16, 1024});
    settings.push_back({"local size 128", 128, 0});
  }
  std::vector<std::string> scenes = repository_scenes();
  for (const char* name : {"area.ray", "glass.ray", "test2.ray"}) scenes.push_back(test_scene(name));
  REQUIRE(scenes.size() >= 20);
  for (const std::string& path : scenes) {
    for (const std::string& integrator : integrator_names()) {
      const auto with = [&](const Setting& s) {
        return [&, s](RenderOptions& o) {
          o.width = width;
          o.height = height;
          o.samples = std::min(o.samples, 2);
          o.integrator = integrator;
          o.local_size = s.local_size;
          o.wavefront = s.wavefront;
        };
      };
      const FloatImage pocl = render_file(path, with(settings[0]), "portable computing language");
      for (const Setting& s : settings) {
        INFO(path << ", " << integrator
                  << ", " << s.what << ", on " << device().name());
        CHECK(same_bits(render_file(path, with(s)), pocl));
      }
    }
  }
}

TEST_CASE("the test device renders PoCL's bits in path mode", "[same-bytes][path]") {
  const bool interpreter = device().device().platform().name() == "Oclgrind";
  const int side = interpreter ? 8 : 32;
  // Glowing spheres and triangles (the glow light's samples and the hits' MIS weights), an
  // environment image (its samples, the escaping paths' weights, the lookups), and a mesh whose
  // faces take their MTL materials (the per-triangle material rows).
  for (const std::string& path : {test_scene("path-lobes.ray"), test_scene("area.ray"),
                                  test_scene("path/glow_sphere.ray"), test_scene("path/glow_mesh.ray"),
                                  test_scene("path/environment.ray"), test_scene("path/mtl.ray")}) {
    for (const std::string& integrator : integrator_names()) {
      const auto with = [&](std::uint32_t wavefront) {
        return [&, wavefront](RenderOptions& o) {
          o.width = o.height = side;
          o.mode = RenderMode::Path;
          o.samples = 2;
          o.integrator = integrator;
          o.wavefront = wavefront;
        };
      };
      const FloatImage pocl = render_file(path, with(0), "portable computing language");
      INFO(path << ", " << integrator_entry(integrator).name << ", on " << device().name());
      CHECK(same_bits(render_file(path, with(0)), pocl));
      if (!interpreter) CHECK(same_bits(render_file(path, with(1024)), pocl));
    }
  }
}

TEST_CASE("the test device renders PoCL's bits of the distribution effects in every mode",
          "[same-bytes][motion]") {
  // scenes/motion.ray: a thin lens, a rolling ball and a spinning cube, a glowing mesh and an
  // environment image.
  const bool interpreter = device().device().platform().name() == "Oclgrind";
  const int side = interpreter ? 8 : 32;
  const std::string path = std::string(CLRT_SOURCE_DIR) + "/scenes/motion.ray";
  for (const RenderMode mode : {RenderMode::Cast, RenderMode::Trace, RenderMode::Path}) {
    for (const std::string& integrator : integrator_names()) {
      const auto with = [&](RenderOptions& o) {
        o.width = o.height = side;
        o.mode = mode;
        o.samples = 4;
        o.integrator = integrator;
      };
      const FloatImage pocl = render_file(path, with, "portable computing language");
      INFO(static_cast<int>(mode) << ", " << integrator << ", on " << device().name());
      CHECK(same_bits(render_file(path, with), pocl));
    }
  }
}
