#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "test_files.hpp"

using clrt::ImageError;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

Bytes with_raster(const std::string& header, const Bytes& raster) {
  Bytes file = bytes_of(header);
  file.insert(file.end(), raster.begin(), raster.end());
  return file;
}

Rgba8Image read_ppm_bytes(const ScratchDir& dir, const Bytes& bytes) {
  const std::string path = dir.file("in.ppm");
  write_bytes(path, bytes);
  return clrt::read_ppm(path);
}

}  // namespace

TEST_CASE("PPM is binary P6, maxval 255, RGB without alpha", "[image][ppm]") {
  ScratchDir dir;
  const std::string path = dir.file("a.ppm");
  clrt::write_image(path, Rgba8Image{2, 1, {{255, 0, 10, 255, 1, 2, 3, 128}}});
  CHECK(read_bytes(path) ==
        Bytes{'P', '6', '\n', '2', ' ', '1', '\n', '2', '5', '5', '\n', 255, 0, 10, 1, 2, 3});
}

TEST_CASE("PPM reader reads back what the writer wrote, opaque", "[image][ppm]") {
  ScratchDir dir;
  const std::string path = dir.file("a.ppm");
  clrt::write_image(path, Rgba8Image{1, 2, {{9, 8, 7, 255, 6, 5, 4, 255}}});
  const Rgba8Image back = clrt::read_ppm(path);
  CHECK(back.width == 1);
  CHECK(back.height == 2);
  CHECK(back.frames == std::vector<Bytes>{{9, 8, 7, 255, 6, 5, 4, 255}});
}

TEST_CASE("PPM reader accepts comments, plain P3 and other maxvals", "[image][ppm]") {
  ScratchDir dir;
  SECTION("P6 with comments in the header") {
    const Rgba8Image image =
        read_ppm_bytes(dir, with_raster("P6 # made by hand\n1 1\n# maxval next\n255\n", {1, 2, 3}));
    CHECK(image.frames == std::vector<Bytes>{{1, 2, 3, 255}});
  }
  SECTION("P3, maxval 10: 3 -> 76.5 -> 77, 7 -> 178.5 -> 179") {
    const Rgba8Image image =
        read_ppm_bytes(dir, bytes_of("P3\n2 1\n10\n0 3 7\n# comment\n10 5 1\n"));
    CHECK(image.width == 2);
    CHECK(image.frames == std::vector<Bytes>{{0, 77, 179, 255, 255, 128, 26, 255}});
  }
  SECTION("P6 with maxval above 255 has two big-endian bytes per sample") {
    // 500 / 1000 -> 127.5 -> 128; 1000 -> 255; 0x0102 = 258 -> 65.79 -> 66
    const Rgba8Image image =
        read_ppm_bytes(dir, with_raster("P6\n1 1\n1000\n", {0x01, 0xf4, 0x03, 0xe8, 0x01, 0x02}));
    CHECK(image.frames == std::vector<Bytes>{{128, 255, 66, 255}});
  }
}

TEST_CASE("PPM reader rejects malformed files, naming them", "[image][ppm]") {
  ScratchDir dir;
  const std::string path = dir.file("in.ppm");
  const auto rejects = [&](const Bytes& bytes, const std::string& reason) {
    write_bytes(path, bytes);
    CHECK_THROWS_WITH(clrt::read_ppm(path), Contains(path) && Contains(reason));
  };
  rejects(with_raster("P6\n2 1\n255\n", {1, 2, 3, 4, 5}), "truncated");
  rejects(with_raster("P6\n1 1\n255\n", {1, 2, 3, 4}), "extra data");
  rejects(bytes_of("P3\n1 1\n255\n1 2\n"), "expected the sample");
  rejects(bytes_of("P3\n1 1\n9\n1 2 10\n"), "exceeds 9");
  rejects(with_raster("P6\n1 1\n300\n", {0x01, 0x2d, 0, 0, 0, 0}), "exceeds maxval");
  rejects(bytes_of("P5\n1 1\n255\n\x01"), "the file holds a PGM image; clrt reads FSF, PNG, PPM");
  rejects(bytes_of("P9\n1 1\n255\n\x01"), "P6 or P3");
  rejects(bytes_of("P6\n0 1\n255\n"), "width is below 1");
  rejects(bytes_of("P6\n1 1\n70000\n"), "maxval exceeds 65535");
  // A header asking for 2^62 samples must fail on the size check, before any allocation.
  rejects(bytes_of("P6\n2147483647 2147483647\n255\n"),
          "the PPM's 2147483647x2147483647 pixels are more than clrt reads");
  rejects(bytes_of("P6\n65536 4096\n255\n"), "truncated");  // 2^28 pixels: within the limits
}
