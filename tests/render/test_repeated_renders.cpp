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
  lane.push_back({std::make_unique<DeviceContext>(prepared.context->lane()), prepared.program, prepared.mode,
                  prepared.features});
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

namespace repeated_renders_test {

// Devices are prepared before the scene is read, with the program for still scenes without
// textures. Renders `scene` at 40x30, 4 samples per pixel, in trace mode (the mode render_on's
// programs are for) on a device so prepared, checks that it gets the bits of its own program,
// and returns them with the setup and the prepared device.
struct PreparedRender {
  RenderSetup setup;
  std::vector<PreparedDevice> prepared;
  FloatImage expected;
};

PreparedRender render_on_prepared(const Scene& scene) {
  PreparedRender r;
  r.setup.options = RenderOptions::from_scene(scene);
  r.setup.options.width = 40;
  r.setup.options.height = 30;
  r.setup.options.samples = 4;
  r.setup.options.mode = RenderMode::Trace;
  r.setup.devices = select_devices(test_device_spec());
  r.prepared = prepare_devices(r.setup.devices, r.setup.options.mode);
  REQUIRE(r.prepared.size() == 1);
  REQUIRE(r.prepared.front().features == SceneFeatures{});
  Renderer own_program(scene, build_geometry(scene), r.setup);
  r.expected = std::get<FloatImage>(own_program.render(render_region(r.setup.options), false));
  CHECK(same_bits(render_on(scene, r.setup, r.prepared.front()), r.expected));
  return r;
}

// A scene with moving objects must get the program that places them (a still program leaves
// every object at its first pose, which this scene's spinning cube and rolling ball are not for
// most of the shutter).
TEST_CASE("a program prepared for still scenes is replaced for a scene with motion",
          "[render][repeated][motion]") {
  const Scene scene = load_scene(std::string(CLRT_SOURCE_DIR) + "/scenes/motion.ray");
  const PreparedRender r = render_on_prepared(scene);
  // What the still program renders of this scene is not that image.
  Scene first_pose = scene;
  first_pose.end_transforms.clear();
  for (InstanceSpec& instance : first_pose.instances) instance.motion = -1;
  CHECK_FALSE(same_bits(render_on(first_pose, r.setup, r.prepared.front()), r.expected));
}

// Likewise a scene with textures must get the program that reads them: the prepared program
// would render every material plain.
TEST_CASE("a program prepared for scenes without textures is replaced for a textured scene",
          "[render][repeated][texture]") {
  const Scene scene = load_scene(std::string(CLRT_SOURCE_DIR) + "/scenes/textures.ray");
  const PreparedRender r = render_on_prepared(scene);
  // Without its textures the scene is another image.
  Scene plain = scene;
  for (MaterialSpec& m : plain.materials) m.textures = {-1, -1, -1, -1};
  plain.textures.clear();
  CHECK_FALSE(same_bits(render_on(plain, r.setup, r.prepared.front()), r.expected));
}

}  // namespace repeated_renders_test
