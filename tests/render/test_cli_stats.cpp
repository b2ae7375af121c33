// What the executable reports: --stats in both forms, --quiet, progress only on a terminal,
// and a refused allocation.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt::test;

namespace {

std::string render_args(const std::string& scene, ScratchDir& dir) {
  return quoted(test_scene(scene)) + " --resolution 40x30 -o " + dir.file("out.png");
}

nlohmann::json json_stats(const std::string& extra) {
  ScratchDir dir;
  const CommandResult r = run_clrt(render_args("reflect.ray", dir) + " --spp 4 -q --stats=json" + extra);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.output);
}

}  // namespace

TEST_CASE("the JSON statistics count rays by kind, passes and kernels", "[cli][stats]") {
  const nlohmann::json stats = json_stats("");
  const nlohmann::json& rays = stats["rays"];
  CHECK(rays["camera"] == 40 * 30 * 4);
  const std::uint64_t shadow = rays["shadow"], reflection = rays["reflection"];
  CHECK(shadow > 0);
  CHECK(reflection > 0);  // reflect.ray's spheres and floor are all reflective
  CHECK(rays["refraction"] == 0);
  CHECK(rays["total"] == 40 * 30 * 4 + shadow + reflection);
  CHECK(stats["mrays_per_second"].get<double>() > 0);
  CHECK(stats["integrator"] == "wavefront");
  REQUIRE(stats["devices"].size() == 1);
  CHECK(stats["devices"][0]["opencl_c"].get<std::string>().find("OpenCL C") == 0);
  for (const char* kernel : {"generate", "intersect", "shade", "shadow", "compact_scatter",
                             "gather_shadows", "accumulate_samples", "resolve"}) {
    INFO(kernel);
    CHECK(stats["kernels"][kernel]["launches"].get<int>() > 0);
  }
  // Pass 0 holds exactly the camera rays; reflect.ray's maxdepth 5 gives at most 6 passes, and
  // the shadow rays of the passes add up to the total.
  const nlohmann::json& passes = stats["passes"];
  REQUIRE(passes.size() > 1);
  CHECK(passes.size() <= 6);
  CHECK(passes[0]["rays"] == 40 * 30 * 4);
  std::uint64_t pass_shadows = 0;
  for (const auto& p : passes) pass_shadows += p["shadow_rays"].get<std::uint64_t>();
  CHECK(pass_shadows == shadow);
}

TEST_CASE("each device's share of the frame: its camera samples, which add up to the frame's",
          "[cli][stats]") {
  ScratchDir dir;
  const CommandResult r =
      run_clrt(render_args("reflect.ray", dir) + " --spp 4 -q --stats=json --device all --wavefront 1024",
               "POCL_DEVICES='pthread pthread'");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json stats = nlohmann::json::parse(r.output);
  REQUIRE(stats["devices"].size() == 2);
  std::uint64_t samples = 0;
  double shares = 0;
  for (const nlohmann::json& d : stats["devices"]) {
    samples += d["camera_samples"].get<std::uint64_t>();
    shares += d["frame_share"].get<double>();
  }
  CHECK(samples == 40 * 30 * 4);
  CHECK(shares == Approx(1));
  const CommandResult text =
      run_clrt(render_args("reflect.ray", dir) + " --spp 4 -q --stats --device all --wavefront 1024",
               "POCL_DEVICES='pthread pthread'");
  CHECK(text.output.find("% of the frame\n") != std::string::npos);
  // One device traces the whole frame.
  CHECK(json_stats("")["devices"][0]["frame_share"] == 1.0);
}

TEST_CASE("the kernels' shares add up to the busy time and their intervals to more",
          "[cli][stats]") {
  for (const char* lanes : {" --lanes 1", " --lanes 3 --wavefront 1024"}) {
    INFO(lanes);
    const nlohmann::json stats = json_stats(lanes);
    double shares = 0, intervals = 0;
    for (const auto& [name, k] : stats["kernels"].items()) {
      CHECK(k["share_seconds"].get<double>() <= k["device_seconds"].get<double>() * (1 + 1e-9));
      shares += k["share_seconds"].get<double>();
      intervals += k["device_seconds"].get<double>();
    }
    const double busy = stats["devices"][0]["busy_seconds"];
    CHECK(shares == Approx(busy).epsilon(1e-6));
    CHECK(intervals >= busy * (1 - 1e-6));
  }
}

TEST_CASE("the megakernel reports the wavefront's rays by kind", "[cli][stats]") {
  const nlohmann::json wavefront = json_stats("");
  const nlohmann::json megakernel = json_stats(" --integrator megakernel");
  CHECK(megakernel["integrator"] == "megakernel");
  CHECK(megakernel["rays"] == wavefront["rays"]);
  CHECK(megakernel["kernels"]["megakernel"]["launches"].get<int>() > 0);
  CHECK(megakernel["passes"].empty());
}

TEST_CASE("the text statistics are a table, and quiet alone prints nothing", "[cli][stats]") {
  ScratchDir dir;
  const CommandResult table = run_clrt(render_args("test2.ray", dir) + " -q --stats");
  REQUIRE(table.exit_code == 0);
  CHECK(table.output.find("rays:") != std::string::npos);
  CHECK(table.output.find("kernels:") != std::string::npos);
  CHECK(table.output.find("passes:") != std::string::npos);
  CHECK(table.output.find("(40x30, 1 sample per pixel)") != std::string::npos);
  const CommandResult two = run_clrt(render_args("test2.ray", dir) + " -q --stats --spp 2");
  REQUIRE(two.exit_code == 0);
  CHECK(two.output.find("(40x30, 2 samples per pixel)") != std::string::npos);
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
