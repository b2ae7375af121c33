// Tiles a farm can stitch: the image of a region records where it belongs (PNG text chunk, EXR
// data window), and clrt-img stitch assembles a set of tiles into the bytes of a single render.
#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "image/image.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const std::string kScene = " -q --resolution 37x23 --spp 3 --seed 4 ";

// Four tiles of unequal sizes covering the 37x23 image exactly once.
const std::vector<std::string> kTiles = {"0,20,0,9", "20,37,0,9", "0,11,9,23", "11,37,9,23"};

std::optional<Placement> placement_of(const std::string& path) {
  return std::visit([](const auto& image) { return image.placement; }, read_any_image(path));
}

}  // namespace

TEST_CASE("a tile records its place, and stitched tiles have a single render's bytes",
          "[cli][tiles]") {
  for (const std::string ext : {"png", "exr"}) {
    ScratchDir dir;
    INFO(ext);
    const std::string scene = quoted(test_scene("area.ray")) + kScene;
    const CommandResult full = run_clrt(scene + "-o " + dir.file("full." + ext));
    REQUIRE(full.exit_code == 0);
    std::string tiles;
    for (std::size_t k = 0; k < kTiles.size(); ++k) {
      const std::string tile = dir.file("tile" + std::to_string(k) + "." + ext);
      const CommandResult r = run_clrt(scene + "--pixel-bounds " + kTiles[k] + " -o " + tile);
      INFO(r.output);
      REQUIRE(r.exit_code == 0);
      tiles += " " + tile;
    }
    CHECK(placement_of(dir.file("tile3." + ext)) == Placement{11, 9, 37, 23});
    CHECK_FALSE(placement_of(dir.file("full." + ext)));
    const CommandResult stitched =
        run_program(CLRT_IMG_EXE, "stitch " + dir.file("stitched." + ext) + tiles);
    INFO(stitched.output);
    REQUIRE(stitched.exit_code == 0);
    CHECK(file_bytes(dir.file("stitched." + ext)) == file_bytes(dir.file("full." + ext)));
  }
}
