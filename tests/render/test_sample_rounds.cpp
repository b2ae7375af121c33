// Rounds of samples (src/render/sample_rounds.hpp): how a render's samples are split, that the
// split never changes a bit of the image (whatever the wavefront, lanes or integrator make of
// it), and that the progress line counts the samples per pixel done.
#include <catch2/catch.hpp>

#include <chrono>
#include <string>

#include "device/device_select.hpp"
#include "render/renderer.hpp"
#include "render/sample_rounds.hpp"
#include "cl_fixture.hpp"
#include "render_support.hpp"
#include "scene/scene.hpp"

using namespace clrt;

TEST_CASE("a render's samples are split into few rounds that keep the devices busy", "[rounds]") {
  SECTION("one sample per pixel, or a small image, is one round") {
    CHECK(sample_rounds(1, 1920 * 1080, 65536).size() == 1);
    const auto small = sample_rounds(256, 32 * 32, 65536);
    REQUIRE(small.size() == 1);
    CHECK(small[0].first == 0);
    CHECK(small[0].count == 256);
    CHECK(small[0].last());
  }
  SECTION("a large image takes one sample per round, up to the most rounds") {
    const auto rounds = sample_rounds(16, 1920 * 1080, 65536);
    REQUIRE(rounds.size() == 16);
    for (std::uint32_t r = 0; r < 16; ++r) {
      CHECK(rounds[r].first == r);
      CHECK(rounds[r].count == 1);
      CHECK(rounds[r].total == 16);
      CHECK(rounds[r].last() == (r == 15));
    }
    CHECK(sample_rounds(1000, 1920 * 1080, 65536).size() == kMaxSampleRounds - 1);  // 16 each
  }
  SECTION("each round holds several wavefronts' worth of rays") {
    // 4 x 65536 rays in flight over 10000 pixels: 27 samples a round, the last takes the rest.
    const auto rounds = sample_rounds(100, 10000, 65536);
    REQUIRE(rounds.size() == 4);
    CHECK(rounds[0].count == 27);
    CHECK(rounds[3].first == 81);
    CHECK(rounds[3].count == 19);
  }
  SECTION("a resumed render's rounds start after the samples taken before, in the same sizes") {
    const auto rounds = sample_rounds(100, 10000, 65536, 30);
    REQUIRE(rounds.size() == 3);
    CHECK(rounds[0].first == 30);
    CHECK(rounds[0].count == 27);
    CHECK(rounds[2].first == 84);
    CHECK(rounds[2].count == 16);
    CHECK(rounds[2].last());
    CHECK(sample_rounds(100, 10000, 65536, 100).empty());
  }
}

namespace {

// A path-traced scene at a size where a wavefront of 1024 rays on one lane takes it in many
// rounds.
RenderSetup path_setup(const Scene& scene, int samples, std::uint32_t wavefront,
                       const std::string& integrator) {
  RenderSetup setup;
  setup.options = RenderOptions::from_scene(scene);
  setup.options.mode = RenderMode::Path;
  setup.options.width = 128;
  setup.options.height = 96;
  setup.options.samples = samples;
  setup.options.wavefront = wavefront;
  setup.options.lanes = 1;
  setup.options.integrator = integrator;
  setup.devices = select_devices(test::test_device_spec());
  return setup;
}

const Scene& glossy_scene() {
  static const Scene scene = load_scene(test::test_scene("path/glossy.ray"));
  return scene;
}

FloatImage path_render(std::uint32_t wavefront, const std::string& integrator, std::uint64_t& rounds) {
  RenderStats stats;
  FloatImage image = render(glossy_scene(), path_setup(glossy_scene(), 12, wavefront, integrator), stats);
  rounds = stats.sample_rounds;
  return image;
}

}  // namespace

TEST_CASE("rounds of samples give the bits of one round", "[rounds][path]") {
  std::uint64_t one = 0, many = 0, mega = 0;
  const FloatImage whole = path_render(1u << 20, "wavefront", one);
  const FloatImage split = path_render(1024, "wavefront", many);
  const FloatImage megakernel = path_render(1024, "megakernel", mega);
  CHECK(one == 1);
  CHECK(many == 12);  // 12288 pixels, 4 x 1024 rays a round at least: one sample a round
  CHECK(mega == many);
  CHECK(test::same_bits(whole, split));
  CHECK(test::same_bits(whole, megakernel));
}

TEST_CASE("the progress line counts samples per pixel in rounds", "[rounds][progress]") {
  const RenderSetup setup = path_setup(glossy_scene(), 3, 1024, "wavefront");
  std::string text;
  Progress progress({[&](const std::string& t) { text += t; }, [] { return 120; }},
                    std::chrono::steady_clock::now);
  Renderer renderer(glossy_scene(), setup);
  const PixelRect region = render_region(setup.options);
  CHECK(renderer.render_work(region) == 128 * 96 * 3);
  progress.start("rendering", renderer.render_work(region));
  renderer.render(region, false, &progress);
  for (const char* spp : {"1/3 spp", "2/3 spp", "3/3 spp"}) {
    INFO(text);
    CHECK(text.find(spp) != std::string::npos);
  }
  CHECK(text.find("100%") != std::string::npos);
}
