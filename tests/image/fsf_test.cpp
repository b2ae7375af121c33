#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "test_files.hpp"

using clrt::ImageError;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

// 2x2 pixels, each with distinct channels so any reordering shows.
Rgba8Image two_by_two() {
  return {2, 2, {{1, 2, 3, 255, 4, 5, 6, 255, 7, 8, 9, 255, 10, 11, 12, 128}}};
}

Bytes u32_le(std::uint32_t v) {
  return {Bytes::value_type(v), Bytes::value_type(v >> 8), Bytes::value_type(v >> 16),
          Bytes::value_type(v >> 24)};
}

// A little-endian FSF header followed by `pixel_bytes` bytes of pixels.
Bytes le_file(std::uint32_t width, std::uint32_t height, std::uint32_t frames,
              std::size_t pixel_bytes) {
  Bytes file = concat({u32_le(575), u32_le(width), u32_le(height), u32_le(frames)});
  file.resize(file.size() + pixel_bytes, 0x55);
  return file;
}

std::string read_error(const std::string& path) {
  try {
    clrt::read_fsf(path);
  } catch (const ImageError& error) {
    return error.what();
  }
  FAIL("read_fsf accepted " << path);
  return {};
}

}  // namespace

TEST_CASE("FSF is written little-endian: magic, width, height, frames, then RGBA from the top",
          "[image][fsf]") {
  ScratchDir dir;
  const std::string path = dir.file("a.fsf");
  const Rgba8Image image = two_by_two();
  clrt::write_image(path, image);
  const Bytes expected = concat({u32_le(575), u32_le(2), u32_le(2), u32_le(1), image.frames[0]});
  CHECK(read_bytes(path) == expected);
  CHECK(Bytes{0x3f, 0x02, 0x00, 0x00} ==
        u32_le(575));  // 575 = 0x23f, the independent check of u32_le

  const Rgba8Image back = clrt::read_fsf(path);
  CHECK(back.width == 2);
  CHECK(back.height == 2);
  CHECK(back.frames == image.frames);
}

TEST_CASE("FSF reader accepts a hand-built big-endian file", "[image][fsf]") {
  ScratchDir dir;
  const std::string path = dir.file("be.fsf");
  write_bytes(path, {0x00, 0x00, 0x02, 0x3f,  // magic 575
                     0x00, 0x00, 0x00, 0x02,  // width 2
                     0x00, 0x00, 0x00, 0x01,  // height 1
                     0x00, 0x00, 0x00, 0x01,  // frames 1
                     10,   20,   30,   255,  40, 50, 60, 0});
  const Rgba8Image image = clrt::read_fsf(path);
  CHECK(image.width == 2);
  CHECK(image.height == 1);
  CHECK(image.frames == std::vector<Bytes>{{10, 20, 30, 255, 40, 50, 60, 0}});

  const clrt::FsfHeader header = clrt::read_fsf_header(path);
  CHECK(header.big_endian);
  CHECK(header.width == 2);
  CHECK(header.height == 1);
  CHECK(header.frames == 1);
}

TEST_CASE("FSF round trips an animation frame by frame", "[image][fsf]") {
  ScratchDir dir;
  const std::string path = dir.file("anim.fsf");
  const Rgba8Image anim{
      1,
      2,
      {{1, 1, 1, 255, 2, 2, 2, 255}, {3, 3, 3, 255, 4, 4, 4, 255}, {5, 5, 5, 255, 6, 6, 6, 255}}};
  clrt::write_image(path, anim);
  CHECK(read_bytes(path).size() == 16 + 3 * 8);
  const Rgba8Image back = clrt::read_fsf(path);
  CHECK(back.width == 1);
  CHECK(back.height == 2);
  CHECK(back.frames == anim.frames);
  CHECK(clrt::read_fsf_header(path).frames == 3);
}

TEST_CASE("FSF reader rejects a file shorter or longer than its header says", "[image][fsf]") {
  ScratchDir dir;
  const std::string truncated = dir.file("short.fsf"), oversized = dir.file("long.fsf");
  write_bytes(truncated, le_file(2, 2, 1, 15));
  write_bytes(oversized, le_file(2, 2, 1, 17));
  CHECK_THAT(read_error(truncated),
             Contains(truncated) && Contains("32 bytes") && Contains("truncated"));
  CHECK_THAT(read_error(oversized), Contains(oversized) && Contains("extra data"));
  CHECK_THROWS_AS(clrt::read_fsf_header(truncated), ImageError);
  CHECK_THROWS_AS(clrt::read_fsf_header(oversized), ImageError);
  // An animation missing its last frame is truncated too.
  write_bytes(truncated, le_file(2, 2, 3, 2 * 16));
  CHECK_THAT(read_error(truncated), Contains("truncated"));
}

TEST_CASE("FSF reader rejects a bad magic, a short header and zero sizes", "[image][fsf]") {
  ScratchDir dir;
  const std::string path = dir.file("bad.fsf");
  Bytes png_like = le_file(1, 1, 1, 4);
  png_like[0] = 0x89, png_like[1] = 'P', png_like[2] = 'N', png_like[3] = 'G';
  write_bytes(path, png_like);
  CHECK_THAT(read_error(path), Contains(path) && Contains("89 50 4e 47") && Contains("575"));

  write_bytes(path, {0x3f, 0x02, 0x00, 0x00, 1, 0, 0});
  CHECK_THAT(read_error(path), Contains("16-byte header"));

  write_bytes(path, le_file(0, 0, 1, 0));
  CHECK_THAT(read_error(path), Contains("zero"));
  write_bytes(path, le_file(1, 1, 0, 0));
  CHECK_THAT(read_error(path), Contains("zero"));
}

TEST_CASE("FSF reader rejects absurd sizes without overflowing or allocating", "[image][fsf]") {
  ScratchDir dir;
  const std::string path = dir.file("huge.fsf");
  // 65536 * 65536 * 4 bytes wraps a 32-bit product to exactly 0, and with 2^30 frames the whole
  // file size wraps 64 bits to 16 bytes: the sizes are refused before any product is taken.
  write_bytes(path, le_file(65536, 65536, 1u << 30, 0));
  CHECK_THAT(read_error(path), Contains("the FSF's 65536x65536 pixels are more than clrt reads"));
  // Within the limits (2^28 pixels), 2^30 frames make 2^60 bytes, counted without wrapping.
  write_bytes(path, le_file(16384, 16384, 1u << 30, 0));
  CHECK_THAT(read_error(path), Contains("1152921504606846992 bytes") && Contains("truncated"));
  write_bytes(path, le_file(16384, 16384, 1, 0));
  CHECK_THAT(read_error(path), Contains("1073741840 bytes"));
  write_bytes(path, le_file(0xffffffffu, 0xffffffffu, 0xffffffffu, 0));
  CHECK_THAT(read_error(path), Contains("too large"));
}

TEST_CASE("FSF info lists size, frames, byte order and bytes", "[image][fsf]") {
  ScratchDir dir;
  const std::string path = dir.file("anim.fsf");
  clrt::write_image(path, Rgba8Image{3, 2, {Bytes(24, 7), Bytes(24, 8)}});
  const clrt::FsfHeader header = clrt::read_fsf_header(path);
  CHECK_FALSE(header.big_endian);
  CHECK(clrt::fsf_file_size(header) == 16 + 2 * 24);
  CHECK(clrt::info_text(clrt::read_image_info(path)) ==
        "format: FSF\nwidth: 3\nheight: 2\nframes: 2\nchannels: RGBA\nsamples: 8-bit\n"
        "placement: none (FSF cannot record one)\nbyte order: little-endian\nbytes: 64\n");

  write_bytes(path, concat({{0x00, 0x00, 0x02, 0x3f, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1},
                            {1, 2, 3, 4}}));
  const clrt::ImageInfo big = clrt::read_image_info(path);
  CHECK(big.details == decltype(big.details){{"byte order", "big-endian"}, {"bytes", "20"}});
  CHECK_THROWS_AS(clrt::fsf_file_size({0xffffffffu, 0xffffffffu, 0xffffffffu, false}), ImageError);
}

TEST_CASE("select_frame picks one frame of an animation, counted from 1", "[image][fsf]") {
  const Rgba8Image anim{1, 1, {{1, 1, 1, 255}, {2, 2, 2, 255}}};
  CHECK(clrt::select_frame(anim, 1).frames == std::vector<Bytes>{{1, 1, 1, 255}});
  CHECK(clrt::select_frame(anim, 2).frames == std::vector<Bytes>{{2, 2, 2, 255}});
  CHECK_THROWS_WITH(clrt::select_frame(anim, 3), Catch::Matchers::Contains("counted from 1"));
  CHECK_THROWS_AS(clrt::select_frame(anim, 0), ImageError);
  CHECK_THROWS_AS(clrt::select_frame(anim, -1), ImageError);
}
