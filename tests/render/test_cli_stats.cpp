// What the executable reports: --stats in both forms, --quiet, progress only on a terminal,
// and a refused allocation.
#include <catch2/catch.hpp>

#include <regex>
#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt::test;

namespace {

// The number after "key": in --stats=json output.
double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  const std::regex pattern("\"" + key + "\": ([0-9.eE+-]+)");
  REQUIRE(std::regex_search(json, m, pattern));
  return std::stod(m[1]);
}

std::string render_args(const std::string& scene, ScratchDir& dir) {
  return quoted(test_scene(scene)) + " --resolution 40x30 -o " + dir.file("out.png");
}

}  // namespace

TEST_CASE("the JSON statistics count rays by kind, passes and kernels", "[cli][stats]") {
  ScratchDir dir;
  const CommandResult r = run_clrt(render_args("reflect.ray", dir) + " --spp 4 -q --stats=json");
  REQUIRE(r.exit_code == 0);
  CHECK(json_number(r.output, "camera") == 40 * 30 * 4);
  const double shadow = json_number(r.output, "shadow");
  const double reflection = json_number(r.output, "reflection");
  CHECK(shadow > 0);
  CHECK(reflection > 0);  // reflect.ray's spheres and floor are all reflective
  CHECK(json_number(r.output, "refraction") == 0);
  CHECK(json_number(r.output, "total") == 40 * 30 * 4 + shadow + reflection);
  CHECK(json_number(r.output, "mrays_per_second") > 0);
  for (const char* kernel : {"generate", "intersect", "shade", "shadow", "compact_scatter",
                             "gather_shadows", "accumulate_samples", "resolve"}) {
    INFO(kernel);
    CHECK(r.output.find(std::string("\"") + kernel + "\": {\"launches\": ") != std::string::npos);
  }
  // Pass 0 holds exactly the camera rays; reflect.ray's maxdepth 5 gives at most 6 passes.
  std::smatch pass0;
  REQUIRE(std::regex_search(r.output, pass0, std::regex("\"passes\": \\[\\{\"rays\": ([0-9]+)")));
  CHECK(std::stod(pass0[1]) == 40 * 30 * 4);
  CHECK(r.output.find("}, {\"rays\"") != std::string::npos);
}

TEST_CASE("the text statistics are a table, and quiet alone prints nothing", "[cli][stats]") {
  ScratchDir dir;
  const CommandResult table = run_clrt(render_args("test2.ray", dir) + " -q --stats");
  REQUIRE(table.exit_code == 0);
  CHECK(table.output.find("rays:") != std::string::npos);
  CHECK(table.output.find("kernels:") != std::string::npos);
  CHECK(table.output.find("passes:") != std::string::npos);
  const CommandResult quiet = run_clrt(render_args("test2.ray", dir) + " -q");
  REQUIRE(quiet.exit_code == 0);
  CHECK(quiet.output.empty());
}

TEST_CASE("without --quiet the device is named, and no progress bar goes to a pipe",
          "[cli][stats]") {
  ScratchDir dir;
  const CommandResult r = run_clrt(render_args("test2.ray", dir));
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.rfind("device 0:0", 0) == 0);
  CHECK(r.output.find("rendering [") == std::string::npos);
}

TEST_CASE("a wavefront the device cannot hold fails naming the buffer", "[cli][memory]") {
  ScratchDir dir;
  // PoCL told it has 1 GiB offers at most 256 MiB in one allocation whatever the machine's
  // memory; the ray queue of 2^26 rays needs 4 GiB.
  const CommandResult r = run_clrt(render_args("test2.ray", dir) + " -q --wavefront 67108864",
                                   "POCL_MEMORY_LIMIT=1");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("the ray queue buffer needs 4096.0 MiB on "));
  CHECK_THAT(r.output, Catch::Contains("more than its largest allocation (256.0 MiB): lower --wavefront"));
  CHECK(file_bytes(dir.file("out.png")).empty());
}
