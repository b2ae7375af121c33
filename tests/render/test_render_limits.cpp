// check_render_limits() against budgets given by hand: the device and host figures a machine
// would report, so that each refusal is tested whatever this machine has; and the queue sizes it
// checks against what the renderer really allocates.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <regex>
#include <string>
#include <tuple>

#include "geometry/geometry_data.hpp"
#include "render/frame_setup.hpp"
#include "render/integrator.hpp"
#include "render/render_limits.hpp"
#include "render/wave_queues.hpp"
#include "render/wave_sizes.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;

namespace {

constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;

MachineBudget roomy_machine() {
  MachineBudget budget;
  budget.host_available = 64 * kGiB;
  DeviceBudget device;
  device.name = "test device";
  device.wavefront = 16384;
  device.max_allocation = 4 * kGiB;
  device.global_memory = 16 * kGiB;
  device.uses_host_memory = true;
  budget.devices.push_back(device);
  return budget;
}

Scene one_sphere() {
  Scene scene;
  scene.instances.push_back(place_instance(ShapeKind::Sphere, Mat4::identity()));
  return scene;
}

RenderOptions options_of(const Scene& scene) { return RenderOptions::from_scene(scene); }

// The exit code and message check_render_limits() refuses with (0 and "" if it accepts).
std::pair<int, std::string> verdict(const Scene& scene, const RenderOptions& options,
                                    const MachineBudget& budget) {
  try {
    check_render_limits(scene, options, budget);
  } catch (const RenderLimitError& e) {
    return {e.exit_code(), e.what()};
  }
  return {0, ""};
}

}  // namespace

TEST_CASE("a small render on a roomy machine goes ahead", "[limits]") {
  const Scene scene = one_sphere();
  CHECK(verdict(scene, options_of(scene), roomy_machine()).first == 0);
}

TEST_CASE("the request's own limits exit 2, whichever loader made the scene", "[limits]") {
  Scene scene = one_sphere();
  RenderOptions o = options_of(scene);
  SECTION("pixels counted in 64 bits") {
    o.width = 65536;
    o.height = 65536;  // 2^32: zero in 32 bits
    const auto [code, message] = verdict(scene, o, roomy_machine());
    CHECK(code == 2);
    CHECK_THAT(message, Catch::Contains("4294967296 pixels, more than the limit of 268435456"));
  }
  SECTION("shadow samples summed in 64 bits") {
    LightSpec area;
    area.kind = "area";
    area.samples = 65536;
    for (int i = 0; i < 17; ++i) scene.lights.push_back(area);
    const auto [code, message] = verdict(scene, o, roomy_machine());
    CHECK(code == 2);
    CHECK_THAT(message, Catch::Contains("the lights take 1114112 shadow-ray samples per shading point"));
  }
  SECTION("depth and samples") {
    o.max_depth = 65537;
    CHECK(verdict(scene, o, roomy_machine()).first == 2);
    o.max_depth = 5;
    o.samples = 0;
    CHECK(verdict(scene, o, roomy_machine()).first == 2);
  }
}

TEST_CASE("a queue larger than the device's largest allocation exits 1 naming it", "[limits]") {
  const Scene scene = one_sphere();
  MachineBudget budget = roomy_machine();
  budget.devices[0].max_allocation = 2 * 16384 * 64 - 1;  // the spawned ray slots need 2 MiB
  const auto [code, message] = verdict(scene, options_of(scene), budget);
  CHECK(code == 1);
  CHECK_THAT(message, Catch::Contains("the spawned ray slot buffer needs 2.0 MiB on test device"));
  CHECK_THAT(message, Catch::Contains("lower --wavefront (now 16384)"));
}

TEST_CASE("each integrator is checked against the buffers it allocates", "[limits]") {
  const Scene scene = one_sphere();
  RenderOptions o = options_of(scene);
  o.integrator = "megakernel";
  MachineBudget budget = roomy_machine();
  // The wavefront's spawned ray slots (2 MiB) exist only in the wavefront's queues.
  budget.devices[0].max_allocation = 2 * 16384 * 64 - 1;
  CHECK(verdict(scene, o, budget).first == 0);
  // The megakernel's own: a count per ray kind per camera sample, 256 KiB.
  budget.devices[0].max_allocation = 16384 * 16 - 1;
  const auto [code, message] = verdict(scene, o, budget);
  CHECK(code == 1);
  CHECK_THAT(message, Catch::Contains("the ray count buffer needs 0.2 MiB on test device"));
}

TEST_CASE("memory needed beyond the device's or the host's exits 1", "[limits]") {
  Scene scene = one_sphere();
  RenderOptions o = options_of(scene);
  MachineBudget budget = roomy_machine();
  SECTION("device memory") {
    budget.devices[0].global_memory = 1 << 20;
    const auto [code, message] = verdict(scene, o, budget);
    CHECK(code == 1);
    CHECK_THAT(message, Catch::Contains("of memory on test device"));
  }
  SECTION("host memory for the image") {
    o.width = 16384;
    o.height = 16384;  // 28 bytes a pixel: 7 GiB
    budget.host_available = 4 * kGiB;
    const auto [code, message] = verdict(scene, o, budget);
    CHECK(code == 1);
    CHECK_THAT(message, Catch::Contains("of host memory (image 7168.0 MiB"));
    budget.host_available = 8 * kGiB;
    CHECK(verdict(scene, o, budget).first == 0);
  }
}

TEST_CASE("queue sizes are computed in 64 bits", "[limits]") {
  const WaveSizes s = wave_sizes(16384, 4, 65536);
  CHECK(s.capacity == 16384);
  CHECK(s.shade_chunk == 1);  // one ray's shadow slots fill a queue's worth
  CHECK(s.shadow_slots == 65536);
  CHECK(s.wave_pixels == 16384);  // a round of one sample per pixel
  const WaveSizes big = wave_sizes(1u << 26, 1, std::uint64_t{1} << 20);
  CHECK(WaveQueues::buffers(big).front().bytes == (std::uint64_t{1} << 26) * 64);  // 4 GiB, no wrap
}

TEST_CASE("the checked buffer sizes are the ones the renderer allocates", "[limits][cli]") {
  const std::string scene_path = test::test_scene("area.ray");
  const Scene scene = load_scene(scene_path);
  const clrt::test::ScratchDir dir;
  struct Case {
    std::string options;
    std::uint64_t wavefront, lanes;
    std::string integrator;
  };
  // The scene asks for 4 samples.
  for (const Case& c : {Case{" --lanes 1", 16384, 1, "wavefront"},
                        Case{" --spp 4 --wavefront 1024 --lanes 3", 1024, 3, "wavefront"},
                        Case{" --integrator megakernel --wavefront 2048 --lanes 2", 2048, 2,
                             "megakernel"}}) {
    INFO(c.options);
    const test::CommandResult r = test::run_clrt(test::quoted(scene_path) +
                                                 " -q --resolution 32x16 --stats=json -o " +
                                                 dir.file("out.png") + c.options);
    REQUIRE(r.exit_code == 0);
    const std::uint64_t reported = nlohmann::json::parse(r.output)["bytes"]["device"];
    RenderOptions o = RenderOptions::from_scene(scene);
    o.samples = 4;
    const GeometryData geometry = build_geometry(scene);
    const FrameData frame = make_frame(scene, geometry, o);
    std::uint64_t expected = geometry.device_bytes() + sizeof(dev::Camera) +
                             sizeof(dev::RenderParams) + sizeof(dev::Material) * frame.materials.size() +
                             sizeof(dev::Light) * frame.lights.size() +
                             sizeof(dev::Texture) * frame.textures->records.size() +
                             sizeof(dev::u32) * frame.textures->texels.size();
    // Every lane has buffers of its own.
    const WaveSizes sizes = wave_sizes(c.wavefront, 4, frame.params.shadow_samples);
    for (const DeviceBuffer& b : integrator_entry(c.integrator).buffers(sizes))
      expected += c.lanes * b.bytes;
    CHECK(reported == expected);
  }
}
