// clrt-img against small files that declare huge images: each is refused from its header, before
// anything of the declared size is allocated, which a cap on the address space (ulimit -v)
// proves.
#include <catch2/catch.hpp>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <string>

#include "image/image.hpp"
#include "png_chunks.hpp"
#include "run_tool.hpp"
#include "skip_test.hpp"

using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

// 256 MiB of address space: clrt-img starts in about 30, and every file here declares 1 GiB or
// more of pixels.
constexpr const char* kAddressSpaceKib = "262144";

// clrt-img `args` with its address space capped; AddressSanitizer's shadow memory cannot be
// reserved under ulimit -v, so its builds run uncapped.
ToolResult run_img_capped(const ScratchDir& dir, const std::string& args) {
#if defined(__SANITIZE_ADDRESS__)
  return run_img(dir, args);
#else
  return run_tool(dir, "sh", "-c " + quoted("ulimit -v " + std::string(kAddressSpaceKib) +
                                            " && exec " + quoted(CLRT_IMG) + " " + args));
#endif
}

// A PNG tile declaring width x height pixels at x,y of a `frame` ("WxH") full frame.
std::string forged_tile(const ScratchDir& dir, const std::string& name, std::uint32_t width,
                        std::uint32_t height, const std::string& at, const std::string& frame) {
  const std::string path = dir.file(name);
  const std::string placement =
      at + " " + std::to_string(width) + "x" + std::to_string(height) + " of " + frame;
  write_bytes(path, png_declaring(width, height, text_chunk("clrt:placement", placement)));
  return path;
}

// clrt's own 4x3 EXR with its data and display windows made 16384 x 16384 (2^28 pixels, 3 GiB
// as floats), padded to hold the offset table that size needs.
std::string forged_exr(const ScratchDir& dir) {
  const std::string path = dir.file("big.exr");
  clrt::write_image(path, clrt::FloatImage(4, 3, std::vector<float>(36, 0.5f)));
  Bytes bytes = read_bytes(path);
  const std::string text(bytes.begin(), bytes.end());
  for (const char* window : {"dataWindow", "displayWindow"}) {
    const std::size_t at = text.find(window);
    REQUIRE(at != std::string::npos);
    const std::size_t x_max = at + std::strlen(window) + 1 + std::strlen("box2i") + 1 + 4 + 8;
    const std::int32_t last = 16383;
    std::memcpy(&bytes[x_max], &last, 4);
    std::memcpy(&bytes[x_max + 4], &last, 4);
  }
  bytes.resize(bytes.size() + 16384, 0);
  write_bytes(path, bytes);
  return path;
}

void check_refused(const ToolResult& result, std::initializer_list<std::string> messages,
                   const std::string& output) {
  INFO(result.err);
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("clrt-img: error: "));
  for (const std::string& message : messages) CHECK_THAT(result.err, Contains(message));
  CHECK_FALSE(std::filesystem::exists(output));
}

}  // namespace

TEST_CASE("stitch refuses tiles that declare a frame larger than clrt reads, from their headers",
          "[img][stitch][limits]") {
  // Two 16384x16384 tiles side by side: a 2^29-pixel frame, which `info` would refuse.
  ScratchDir dir;
  const std::string left = forged_tile(dir, "left.png", 16384, 16384, "0,0", "32768x16384");
  const std::string right = forged_tile(dir, "right.png", 16384, 16384, "16384,0", "32768x16384");
  const std::string out = dir.file("out.png");
  check_refused(run_img_capped(dir, "stitch " + quoted(out) + " " + quoted(left) + " " +
                                        quoted(right)),
                {"the tiles belong to a 32768x16384 frame (536870912 pixels), beyond the 65536 "
                 "pixels a side and 268435456 pixels clrt reads"},
                out);
}

TEST_CASE("stitch and convert refuse, before decoding, images the memory cannot hold",
          "[img][stitch][convert][limits][memory]") {
#if defined(__SANITIZE_ADDRESS__)
  CLRT_SKIP_TEST("AddressSanitizer cannot run under ulimit -v");
#endif
  ScratchDir dir;
  const std::string capped = " MiB available (RLIMIT_AS, ulimit -v)";
  const std::string top = forged_tile(dir, "top.png", 16384, 8192, "0,0", "16384x16384");
  const std::string bottom = forged_tile(dir, "bottom.png", 16384, 8192, "0,8192", "16384x16384");
  const std::string out = dir.file("out.png");
  check_refused(run_img_capped(dir, "stitch " + quoted(out) + " " + quoted(top) + " " +
                                        quoted(bottom)),
                {"stitching 2 tiles into their 16384x16384 frame needs ", capped}, out);

  const std::string png = dir.file("big.png");
  write_bytes(png, png_declaring(16384, 16384));
  const std::string exr = forged_exr(dir);
  for (const std::string& input : {png, exr}) {
    INFO(input);
    const std::string pfm = dir.file("out.pfm");
    check_refused(run_img_capped(dir, "convert " + quoted(input) + " " + quoted(pfm)),
                  {"converting " + input + " needs ", capped}, pfm);
  }
}

namespace {

// An FSF animation of `frames` frames of one pixel each: 4 bytes a frame, and in memory a vector
// and an allocation each.
std::string tiny_frames(const ScratchDir& dir, const std::string& name, std::uint32_t frames) {
  Bytes fsf = concat({{0x3f, 0x02, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}});
  for (int shift = 0; shift < 32; shift += 8) fsf.push_back(static_cast<std::uint8_t>(frames >> shift));
  fsf.resize(fsf.size() + 4 * std::size_t{frames}, 0x80);
  const std::string path = dir.file(name);
  write_bytes(path, fsf);
  return path;
}

}  // namespace

TEST_CASE("convert to GIF counts each frame's own cost and streams the GIF to its file",
          "[img][convert][gif][limits][memory]") {
#if defined(__SANITIZE_ADDRESS__)
  CLRT_SKIP_TEST("AddressSanitizer cannot run under ulimit -v");
#endif
  ScratchDir dir;
  // 5M frames in a 20 MB file held 426 MB when counted at their pixels alone (60 MB): refused
  // now from the header, under the cap of 256 MiB.
  const std::string many = tiny_frames(dir, "many.fsf", 5000000);
  const std::string gif = dir.file("many.gif");
  check_refused(run_img_capped(dir, "convert " + quoted(many) + " " + quoted(gif)),
                {"converting " + many + " needs ", " MiB available (RLIMIT_AS, ulimit -v)"}, gif);
  // 1.5M frames fit, and so does their GIF (37 MB), which is written as it is made rather than
  // held whole beside the frames.
  const std::string fewer = tiny_frames(dir, "fewer.fsf", 1500000);
  const ToolResult fits = run_img_capped(dir, "convert " + quoted(fewer) + " " + quoted(gif));
  INFO(fits.err);
  CHECK(fits.status == 0);
  CHECK(std::filesystem::file_size(gif) > 25 * std::uintmax_t{1500000});
}

TEST_CASE("PFM, PPM and FSF headers declaring more pixels than their files hold are refused",
          "[img][convert][limits]") {
  ScratchDir dir;
  // 16384 x 16384: 2^28 pixels, within what clrt reads, 1 GiB or more of samples.
  Bytes fsf = concat({{0x3f, 0x02, 0, 0}, {0, 0x40, 0, 0}, {0, 0x40, 0, 0}, {1, 0, 0, 0}});
  fsf.resize(64, 7);
  const std::pair<const char*, Bytes> files[] = {
      {"big.pfm", bytes_of("PF\n16384 16384\n-1.0\n" + std::string(64, 'x'))},
      {"big.ppm", bytes_of("P6\n16384 16384\n255\n" + std::string(64, 'x'))},
      {"big.fsf", fsf}};
  for (const auto& [name, bytes] : files) {
    INFO(name);
    write_bytes(dir.file(name), bytes);
    const std::string png = dir.file("out.png");
    check_refused(run_img_capped(dir, "convert " + quoted(dir.file(name)) + " " + quoted(png)),
                  {dir.file(name) + ": ", "truncated"}, png);
  }
}

TEST_CASE("PFM, PPM and FSF files wider than 65536 pixels are refused as PNG and OpenEXR are, "
          "whole as they are",
          "[img][convert][info][limits]") {
  // 100000 x 1, every byte of the raster there: once converted into a PNG or an EXR that
  // `info` refused.
  ScratchDir dir;
  const std::uint32_t wide = 100000;
  Bytes fsf = concat({{0x3f, 0x02, 0, 0}, {0xa0, 0x86, 0x01, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}});
  fsf.resize(16 + 4 * wide, 7);
  const std::pair<const char*, Bytes> files[] = {
      {"wide.pfm", bytes_of("PF\n100000 1\n-1.0\n" + std::string(12 * wide, '\0'))},
      {"wide.ppm", bytes_of("P6\n100000 1\n255\n" + std::string(3 * wide, 'x'))},
      {"wide.fsf", fsf}};
  for (const auto& [name, bytes] : files) {
    INFO(name);
    const std::string in = dir.file(name), format = std::string(name).substr(5);
    write_bytes(in, bytes);
    std::string upper = format;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const std::string message = in + ": the " + upper +
                                "'s 100000x1 pixels are more than clrt reads (at most 65536 a "
                                "side and 268435456 in all)";
    for (const char* out_name : {"out.png", "out.exr"}) {
      const std::string out = dir.file(out_name);
      check_refused(run_img(dir, "convert " + quoted(in) + " " + quoted(out)), {message}, out);
    }
    const ToolResult info = run_img(dir, "info " + quoted(in));
    CHECK(info.status == 1);
    CHECK(info.err == "clrt-img: error: " + message + "\n");
  }
}
