// clrt's image output options: -o - with --format, --format for a file, --exr-pixel.
#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "run_tool.hpp"

using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

const std::string kScene = quoted(CLRT_SOURCE_DIR "/scenes/test2.ray") + " -q --resolution 40x24";

ToolResult run_clrt(const ScratchDir& dir, const std::string& args) {
  return run_tool(dir, CLRT_EXE, kScene + " " + args);
}

}  // namespace

TEST_CASE("clrt -o - writes the image to standard output in the --format given",
          "[cli][output]") {
  ScratchDir dir;
  for (const char* format : {"png", "ppm", "pfm", "fsf", "exr"}) {
    INFO(format);
    const std::string file = dir.file(std::string("file.") + format);
    REQUIRE(run_clrt(dir, "-o " + quoted(file)).status == 0);
    const ToolResult piped = run_clrt(dir, std::string("-o - --format ") + format);
    CHECK(piped.status == 0);
    CHECK(piped.out == read_bytes(file));
  }
  // Statistics go to standard error when standard output holds the image.
  const ToolResult stats = run_clrt(dir, "-o - --format ppm --stats");
  CHECK(stats.status == 0);
  CHECK(stats.out == read_bytes(dir.file("file.ppm")));
  CHECK_FALSE(stats.err.empty());
}

TEST_CASE("clrt --format names the format of a file, whatever its name", "[cli][output]") {
  ScratchDir dir;
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("a.pfm"))).status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("render.out")) + " --format pfm").status == 0);
  CHECK(read_bytes(dir.file("render.out")) == read_bytes(dir.file("a.pfm")));
  const ToolResult default_name =
      run_tool(dir, "sh", "-c " + quoted("cd " + dir.path().string() + " && '" CLRT_EXE "' " +
                                         CLRT_SOURCE_DIR "/scenes/test2.ray -q --resolution "
                                                         "40x24 --format exr"));
  CHECK(default_name.status == 0);
  CHECK(clrt::read_image_info(dir.file("test2.exr")).format == clrt::ImageFormat::Exr);
}

TEST_CASE("clrt writes half EXR by default and float EXR with --exr-pixel float",
          "[cli][output]") {
  ScratchDir dir;
  const std::string pfm = dir.file("a.pfm"), half = dir.file("h.exr"), full = dir.file("f.exr");
  REQUIRE(run_clrt(dir, "-o " + quoted(pfm)).status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(half)).status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(full) + " --exr-pixel float").status == 0);
  const clrt::FloatImage rendered = clrt::read_pfm(pfm);
  CHECK(clrt::read_exr(full).rgb == rendered.rgb);
  const std::string reference = dir.file("reference.exr");
  clrt::write_image(reference, rendered);
  CHECK(read_bytes(half) == read_bytes(reference));
  CHECK(clrt::read_image_info(half).samples == "16-bit float (half)");
}

TEST_CASE("clrt refuses -o - without --format and a --format its extension contradicts, at once",
          "[cli][output]") {
  ScratchDir dir;
  ToolResult result = run_clrt(dir, "-o -");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("--format"));
  CHECK(result.out.empty());
  result = run_clrt(dir, "-o " + quoted(dir.file("out.png")) + " --format exr");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("clrt: error: ") && Contains("names png"));
  CHECK(run_clrt(dir, "-o - --format gif").status == 2);
  CHECK(run_clrt(dir, "-o " + quoted(dir.file("o.exr")) + " --exr-pixel double").status == 2);
  CHECK(dir.entries() == std::set<std::string>{"stdout.bin", "stderr.txt"});
}
