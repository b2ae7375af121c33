// The clrt executable's files and exit codes: every output format, outputs it cannot write,
// scene errors, and device selection.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "render_support.hpp"

using namespace clrt;
using namespace clrt::test;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 40, kHeight = 24;

std::string render_to(const std::string& out) {
  return "'" + test_scene("test2.ray") + "' -q --resolution 40x24 -o '" + out + "'";
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return v;
}

// The names in `dir`, to show that a failed run left nothing behind.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
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
    write_text(dir.file("file"), "x");
    const CommandResult r = run_clrt(render_to(dir.file("file") + "/out.png"));
    INFO(r.output);
    CHECK(r.exit_code != 0);
    CHECK(r.output.find("error") != std::string::npos);
    CHECK(entries(dir.path()) == std::vector<std::string>{"file"});
    CHECK(file_bytes(dir.file("file")) == "x");
  }
  SECTION("it is a directory") {
    fs::create_directory(dir.file("taken.png"));
    const CommandResult r = run_clrt(render_to(dir.file("taken.png")));
    INFO(r.output);
    CHECK(r.exit_code != 0);
    CHECK(r.output.find("error") != std::string::npos);
    CHECK(entries(dir.path()) == std::vector<std::string>{"taken.png"});
    CHECK(fs::is_empty(dir.file("taken.png")));
  }
  SECTION("its extension names no format") {
    const CommandResult r = run_clrt(render_to(dir.file("out.xyz")));
    INFO(r.output);
    CHECK(r.exit_code != 0);
    CHECK(entries(dir.path()).empty());
  }
}

TEST_CASE("a bad scene exits 2 with FILE:LINE:COLUMN: error and touches no output", "[cli][files]") {
  ScratchDir dir;
  const std::string out = dir.file("out.png");
  write_text(out, "keep");
  SECTION("a wrong argument count") {
    write_text(dir.file("bad.ray"), "eye 0 0 5\nsphere\nfov 60 1\n");
    const CommandResult r = run_clrt("'" + dir.file("bad.ray") + "' -q -o '" + out + "'");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(std::regex_search(r.output, std::regex("bad\\.ray:3:8: error: ")));
  }
  SECTION("the lecture's unrepaired light line") {
    write_text(dir.file("lecture.ray"), "sphere\nlight 1 1 1 ambient\nlight 0 6 0 6 0 6 point 3 3 3\n");
    const CommandResult r = run_clrt("'" + dir.file("lecture.ray") + "' -q -o '" + out + "'");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(std::regex_search(r.output, std::regex("lecture\\.ray:3:[0-9]+: error: ")));
  }
  SECTION("a scene file that does not exist") {
    const CommandResult r = run_clrt("'" + dir.file("missing.ray") + "' -q -o '" + out + "'");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(std::regex_search(r.output, std::regex("missing\\.ray:1:1: error: ")));
  }
  CHECK(file_bytes(out) == "keep");
  for (const std::string& name : entries(dir.path()))
    CHECK((name == "out.png" || fs::path(name).extension() == ".ray"));
}

TEST_CASE("a --device that matches nothing exits 1 and lists the devices", "[cli][devices]") {
  ScratchDir dir;
  const CommandResult r = run_clrt(render_to(dir.file("out.png")) + " --device nonsense");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("nonsense") != std::string::npos);
  CHECK(r.output.find("Portable Computing Language") != std::string::npos);
  CHECK(entries(dir.path()).empty());
}

TEST_CASE("listing the devices exits 0 and prints the PoCL device", "[cli][devices]") {
  const CommandResult r = run_clrt("--list-devices");
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(std::regex_search(r.output, std::regex("0:0 .*Portable Computing Language")));
}
