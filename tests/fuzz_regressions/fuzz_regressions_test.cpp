// Replays every input a fuzz target found (tests/fuzz/regressions/TARGET/, see its README), and
// for most targets its seeds too, through the path that target drives: each must now be rejected with its reader's own error
// (scenes: every one found so far is a scene clrt must refuse) or read into a consistent
// result, never crash or throw anything else.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include "fuzz_paths.hpp"

namespace fs = std::filesystem;
using clrt::fuzz::Outcome;

namespace {

const fs::path kRegressions = fs::path(CLRT_SOURCE_DIR) / "tests" / "fuzz" / "regressions";

std::set<fs::path> inputs_of(const std::string& target) {
  std::set<fs::path> files;
  const fs::path dir = kRegressions / target;
  if (fs::is_directory(dir))
    for (const auto& entry : fs::directory_iterator(dir)) files.insert(entry.path());
  return files;
}

}  // namespace

TEST_CASE("every fuzz target's folder of found inputs is one this test replays", "[fuzz]") {
  const std::set<std::string> replayed = {"fuzz_ray_scene", "fuzz_nff_scene", "fuzz_obj_mesh",
                                          "fuzz_image_fsf", "fuzz_image_ppm", "fuzz_image_png",
                                          "fuzz_image_pfm", "fuzz_image_exr",
                                          "fuzz_program_cache", "fuzz_stitch_tiles",
                                          "fuzz_polygon", "fuzz_path_render", "open"};
  for (const auto& entry : fs::directory_iterator(kRegressions))
    if (entry.is_directory()) CHECK(replayed.count(entry.path().filename().string()) == 1);
}

TEST_CASE("scenes the fuzzer found are rejected with a scene error", "[fuzz]") {
  std::set<fs::path> files = inputs_of("fuzz_ray_scene");
  REQUIRE_FALSE(files.empty());
  files.merge(inputs_of("fuzz_nff_scene"));
  for (const fs::path& file : files) {
    INFO(file);
    CHECK(clrt::fuzz::ray_scene(file.string()) == Outcome::Rejected);
  }
}

TEST_CASE("meshes and images, found or seeded, are rejected or read consistently", "[fuzz]") {
  // With the seeds, every target replays some inputs, also those that have found nothing yet
  // (FSF, PPM, PFM): a loop over an empty folder alone would check nothing.
  const fs::path seeds = fs::path(CLRT_SOURCE_DIR) / "tests" / "fuzz" / "seeds";
  for (const std::string target : {"fuzz_obj_mesh", "fuzz_image_fsf", "fuzz_image_ppm", "fuzz_image_png",
                                   "fuzz_image_pfm", "fuzz_image_exr"}) {
    INFO(target);
    std::set<fs::path> files = inputs_of(target);
    for (const auto& entry : fs::directory_iterator(seeds / target)) files.insert(entry.path());
    REQUIRE_FALSE(files.empty());
    for (const fs::path& file : files) {
      INFO(file);
      if (target == "fuzz_obj_mesh")
        CHECK_NOTHROW(clrt::fuzz::obj_mesh(file.string()));
      else
        CHECK_NOTHROW(clrt::fuzz::image(file.string()));
    }
  }
}

TEST_CASE("cache entries, tiles and polygons, found or seeded, keep every promise", "[fuzz]") {
  // Their seeds too: each seed is a case the path must accept (or refuse) as it says.
  const std::pair<const char*, Outcome (*)(const std::string&)> targets[] = {
      {"fuzz_program_cache", clrt::fuzz::program_cache_entry},
      {"fuzz_stitch_tiles", clrt::fuzz::stitch_tiles},
      {"fuzz_polygon", clrt::fuzz::polygon}};
  const fs::path seeds = fs::path(CLRT_SOURCE_DIR) / "tests" / "fuzz" / "seeds";
  for (const auto& [target, path] : targets) {
    std::set<fs::path> files = inputs_of(target);
    for (const auto& entry : fs::directory_iterator(seeds / target)) files.insert(entry.path());
    for (const fs::path& file : files) {
      INFO(file);
      const Outcome expected = file.filename() == "overlap.txt" ? Outcome::Rejected : Outcome::Accepted;
      CHECK(path(file.string()) == expected);
    }
  }
}

TEST_CASE("path-mode scenes, found or seeded, render finite values or are refused", "[fuzz][path]") {
  // Those named refused-* are scenes the reader now refuses; the others must render.
  std::set<fs::path> files = inputs_of("fuzz_path_render");
  REQUIRE_FALSE(files.empty());
  const fs::path seeds = fs::path(CLRT_SOURCE_DIR) / "tests" / "fuzz" / "seeds" / "fuzz_path_render";
  for (const auto& entry : fs::directory_iterator(seeds)) files.insert(entry.path());
  for (const fs::path& file : files) {
    INFO(file);
    const bool refused = file.filename().string().rfind("refused-", 0) == 0;
    CHECK(clrt::fuzz::path_render(file.string()) == (refused ? Outcome::Rejected : Outcome::Accepted));
  }
}
