// A process that renders many times on one device (a library's user, a farm's worker) keeps
// the bits render after render, with every render's buffers made and freed on one context and
// program. On Intel's CPU runtime such renders crashed inside the kernels in most runs until
// clrt wrote every buffer once when it allocates it (docs/devices.md); under test_render@intel
// this case is the reproducer.
#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "cl_fixture.hpp"
#include "device/device_select.hpp"
#include "geometry/geometry_data.hpp"
#include "render/device_preparation.hpp"
#include "render/renderer.hpp"
#include "render_support.hpp"
#include "scene/scene.hpp"
#include "render/integrator_names.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

// One render of `setup` on `prepared`'s context and program, through a lane of its own.
FloatImage render_on(const Scene& scene, const RenderSetup& setup, const PreparedDevice& prepared) {
  std::vector<PreparedDevice> lane;
  lane.push_back({std::make_unique<DeviceContext>(prepared.context->lane()), prepared.program});
  Renderer renderer(scene, build_geometry(scene), setup, std::move(lane));
  FloatImage image = std::get<FloatImage>(renderer.render(render_region(setup.options), false));
  RenderStats stats;
  renderer.report(stats);
  return image;
}

}  // namespace

TEST_CASE("renders that share one context and program keep their bits, render after render",
          "[render][repeated]") {
  for (const char* name : {"reflect.ray", "cornell.ray"}) {
    const Scene scene = load_scene(std::string(CLRT_SOURCE_DIR) + "/scenes/" + name);
    RenderSetup setup;
    setup.options = RenderOptions::from_scene(scene);
    setup.options.width = 23;
    setup.options.height = 17;
    setup.options.samples = 2;
    setup.options.wavefront = 1024;
    setup.options.region = PixelRect{3, 2, 9, 11};
    setup.devices = select_devices(test_device_spec());
    const std::vector<PreparedDevice> prepared = prepare_devices(setup.devices, setup.options.mode);
    REQUIRE(prepared.size() == 1);
    for (const std::string& integrator : integrator_names()) {
      setup.options.integrator = integrator;
      const FloatImage first = render_on(scene, setup, prepared.front());
      for (int i = 1; i < 30; ++i) {
        INFO(name << ", " << integrator << ", render " << i + 1);
        CHECK(same_bits(render_on(scene, setup, prepared.front()), first));
      }
    }
  }
}
