// Animation: --frames renders a turntable in one process; each frame has the bytes of a single
// render with that frame's eye; FSF holds the frames in one file, other formats one numbered
// file each; --frame-range renders a farm's share with the same bytes; bad requests fail first.
#include <catch2/catch.hpp>

#include <string>

#include "image/image.hpp"
#include "render/orbit.hpp"
#include "render/renderer.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

constexpr std::uint32_t kFrames = 5;
const std::string kSize = " --resolution 31x19 --spp 2 ";

// Frame `frame` (from 1) of a kFrames turntable of `orbit` degrees, rendered as a still with
// the frame's eye in this process and written as PNG.
std::string still_of_frame(const std::string& scene_path, std::uint32_t frame, double orbit,
                           const ScratchDir& dir) {
  Scene scene = load_scene(scene_path);
  scene.camera = orbit_camera(scene.camera, orbit, frame - 1, kFrames);
  RenderSetup setup;
  setup.options = RenderOptions::from_scene(scene);
  setup.options.width = 31;
  setup.options.height = 19;
  setup.options.samples = 2;
  setup.devices = select_devices("cpu");
  RenderStats stats;
  const std::string path = dir.file("still-" + std::to_string(frame) + ".png");
  write_image(path, render(scene, setup, stats));
  return file_bytes(path);
}

}  // namespace

TEST_CASE("every frame of a turntable has the bytes of a still with that frame's eye",
          "[cli][animation]") {
  ScratchDir dir;
  const std::string scene = test_scene("area.ray");
  const CommandResult r =
      run_clrt(quoted(scene) + " -q" + kSize + "--frames 5 --orbit 90 -o " + dir.file("turn.png"));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (std::uint32_t frame = 1; frame <= kFrames; ++frame) {
    INFO("frame " << frame);
    const std::string file = dir.file("turn-000" + std::to_string(frame) + ".png");
    CHECK(file_bytes(file) == still_of_frame(scene, frame, 90, dir));
  }
  CHECK(file_bytes(dir.file("turn-0001.png")) != file_bytes(dir.file("turn-0002.png")));
  CHECK(file_bytes(dir.file("turn-0006.png")).empty());
}

TEST_CASE("FSF holds the frames in one file, and a frame range is the same frames",
          "[cli][animation]") {
  ScratchDir dir;
  const std::string base = quoted(test_scene("reflect.ray")) + " -q" + kSize + "--frames 5 ";
  REQUIRE(run_clrt(base + "-o " + dir.file("all.fsf")).exit_code == 0);
  REQUIRE(run_clrt(base + "--frame-range 2:4 -o " + dir.file("part.fsf")).exit_code == 0);
  REQUIRE(run_clrt(base + "-o " + dir.file("all.png")).exit_code == 0);
  const Rgba8Image all = read_fsf(dir.file("all.fsf"));
  const Rgba8Image part = read_fsf(dir.file("part.fsf"));
  REQUIRE(all.frames.size() == 5);
  REQUIRE(part.frames.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) CHECK(part.frames[k] == all.frames[k + 1]);
  for (std::uint32_t frame = 1; frame <= kFrames; ++frame) {
    INFO("frame " << frame);
    const Rgba8Image png = read_png(dir.file("all-000" + std::to_string(frame) + ".png"));
    CHECK(png.frames[0] == all.frames[frame - 1]);
  }
}

TEST_CASE("the statistics report the frames and frames per second", "[cli][animation]") {
  ScratchDir dir;
  const CommandResult r = run_clrt(quoted(test_scene("test2.ray")) + " -q" + kSize +
                                   "--frames 3 --stats=json -o " + dir.file("a.fsf"));
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("\"frames\": 3") != std::string::npos);
  CHECK(r.output.find("\"frames_per_second\": ") != std::string::npos);
}

TEST_CASE("a bad animation request fails before any work, leaving no file", "[cli][animation]") {
  ScratchDir dir;
  const std::string base = quoted(test_scene("test2.ray")) + kSize;
  for (const char* bad : {"--frames 5 --frame-range 0:2", "--frames 5 --frame-range 4:3",
                          "--frames 5 --frame-range 1:6", "--frames 5 --frame-range 2",
                          "--orbit 90", "--frame-range 1:1", "--frames 0"}) {
    const CommandResult r = run_clrt(base + bad + " -o " + dir.file("x.png"));
    INFO(bad << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("clrt: error:") != std::string::npos);
    CHECK(dir.entries().empty());
  }
  const CommandResult pipe = run_clrt(base + "--frames 3 -o - --format png");
  CHECK(pipe.exit_code == 2);
  CHECK(pipe.output.find("only as FSF") != std::string::npos);
}
