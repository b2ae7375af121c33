// The clrt executable's files and exit codes: every output format, outputs it cannot write,
// scene errors, and device selection.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 40, kHeight = 24;

std::string render_to(const std::string& out) {
  return quoted(test_scene("test2.ray")) + " -q --resolution 40x24 -o " + quoted(out);
}

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return v;
}

}  // namespace

TEST_CASE("every output format is written, holding the same picture", "[cli][files]") {
  ScratchDir dir;
  for (const char* ext : {"png", "ppm", "fsf", "pfm"}) {
    const CommandResult r = run_clrt(render_to(dir.file(std::string("out.") + ext)));
    INFO(ext << ": " << r.output);
    CHECK(r.exit_code == 0);
  }
  const std::string png = file_bytes(dir.file("out.png")), ppm = file_bytes(dir.file("out.ppm"));
  const std::string fsf = file_bytes(dir.file("out.fsf")), pfm = file_bytes(dir.file("out.pfm"));
  CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  CHECK(ppm.compare(0, 2, "P6") == 0);
  REQUIRE(fsf.size() == 16u + 4u * kWidth * kHeight);
  CHECK(le32(fsf, 0) == 575);
  CHECK(le32(fsf, 4) == kWidth);
  CHECK(le32(fsf, 8) == kHeight);
  CHECK(le32(fsf, 12) == 1);
  const std::string pfm_header = "PF\n40 24\n-1.0\n";
  CHECK(pfm.compare(0, pfm_header.size(), pfm_header) == 0);
  CHECK(pfm.size() == pfm_header.size() + 12u * kWidth * kHeight);

  // The 8-bit files hold the same opaque pixels, those of the same render in this process.
  const Rgba8Image expected = quantize(render_file(test_scene("test2.ray"), [](RenderOptions& o) {
    o.width = kWidth;
    o.height = kHeight;
  }));
  for (const char* ext : {"png", "ppm", "fsf"}) {
    INFO(ext);
    const Rgba8Image image = read_image(dir.file(std::string("out.") + ext));
    CHECK(image.width == kWidth);
    CHECK(image.height == kHeight);
    CHECK(image.frames == expected.frames);
  }
  CHECK(pixel_rgb(expected, 0, 0) == (std::array<int, 3>{128, 0, 128}));
}

TEST_CASE("an output that cannot be written fails and leaves nothing behind", "[cli][files]") {
  ScratchDir dir;
  SECTION("its folder is a file") {
    dir.write("file", "x");
    const CommandResult r = run_clrt(render_to(dir.file("file") + "/out.png"));
    INFO(r.output);
    CHECK(r.exit_code != 0);
    CHECK(r.output.find("error") != std::string::npos);
    CHECK(dir.entries() == std::set<std::string>{"file"});
    CHECK(file_bytes(dir.file("file")) == "x");
  }
  SECTION("it is a directory") {
    fs::create_directory(dir.file("taken.png"));
    const CommandResult r = run_clrt(render_to(dir.file("taken.png")));
    INFO(r.output);
    CHECK(r.exit_code != 0);
    CHECK(r.output.find("error") != std::string::npos);
    CHECK(dir.entries() == std::set<std::string>{"taken.png"});
    CHECK(fs::is_empty(dir.file("taken.png")));
  }
  SECTION("its extension names no format") {
    const CommandResult r = run_clrt(render_to(dir.file("out.xyz")));
    INFO(r.output);
    CHECK(r.exit_code != 0);
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("a bad scene exits 2 with FILE:LINE:COLUMN: error and touches no output", "[cli][files]") {
  ScratchDir dir;
  const std::string out = dir.write("out.png", "keep");
  // Renders `scene` to `out`: it must exit 2 with an error whose start matches `where`.
  const auto rejects = [&](const std::string& scene, const std::string& where) {
    const CommandResult r = run_clrt(quoted(scene) + " -q -o " + quoted(out));
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(std::regex_search(r.output, std::regex(where)));
  };
  SECTION("a wrong argument count") {
    rejects(dir.write("bad.ray", "eye 0 0 5\nsphere\nfov 60 1\n"), "bad\\.ray:3:8: error: ");
  }
  SECTION("the lecture's unrepaired light line") {
    rejects(dir.write("lecture.ray",
                      "sphere\nlight 1 1 1 ambient\nlight 0 6 0 6 0 6 point 3 3 3\n"),
            "lecture\\.ray:3:[0-9]+: error: ");
  }
  SECTION("a scene file that does not exist") {
    rejects(dir.file("missing.ray"),
            "missing\\.ray: error: cannot read the scene file \\(No such file or directory\\)");
  }
  CHECK(file_bytes(out) == "keep");
  for (const std::string& name : dir.entries())
    CHECK((name == "out.png" || fs::path(name).extension() == ".ray"));
}

TEST_CASE("a --device that matches nothing exits 1 and lists the devices", "[cli][devices]") {
  ScratchDir dir;
  const CommandResult r = run_clrt(render_to(dir.file("out.png")) + " --device nonsense");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("nonsense") != std::string::npos);
  CHECK(r.output.find("Portable Computing Language") != std::string::npos);
  CHECK(dir.entries().empty());
}

TEST_CASE("listing the devices exits 0 and prints the PoCL device", "[cli][devices]") {
  const CommandResult r = run_clrt("--list-devices");
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(std::regex_search(r.output, std::regex("0:0 .*Portable Computing Language")));
}
