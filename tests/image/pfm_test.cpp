#include <catch2/catch.hpp>
#include <cstring>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "test_files.hpp"

using namespace clrt::test;
using Catch::Matchers::Contains;

TEST_CASE("PFM is colour PF, scale -1.0 (little-endian), rows bottom to top, unclamped",
          "[image][pfm]") {
  ScratchDir dir;
  const std::string path = dir.file("a.pfm");
  // Row 0 (top): 1, 2, -3. Row 1 (bottom): 0.5, 100, -0.25.
  clrt::write_image(path, clrt::FloatImage{1, 2, {1.0f, 2.0f, -3.0f, 0.5f, 100.0f, -0.25f}});
  // IEEE 754 single precision, least significant byte first, worked out by hand:
  // 0.5 = 3f000000, 100 = 42c80000, -0.25 = be800000, 1 = 3f800000, 2 = 40000000, -3 = c0400000.
  const Bytes expected =
      concat({bytes_of("PF\n1 2\n-1.0\n"),
              {0x00, 0x00, 0x00, 0x3f, 0x00, 0x00, 0xc8, 0x42, 0x00, 0x00, 0x80, 0xbe},
              {0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x40, 0xc0}});
  CHECK(read_bytes(path) == expected);
}

TEST_CASE("PFM of an 8-bit image holds value / 255 and drops alpha", "[image][pfm]") {
  ScratchDir dir;
  const std::string path = dir.file("a.pfm");
  clrt::write_image(path, clrt::Rgba8Image{1, 1, {{255, 0, 255, 7}}});
  CHECK(read_bytes(path) ==
        concat({bytes_of("PF\n1 1\n-1.0\n"),
                {0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x3f}}));
}

TEST_CASE("PFM reads back what it wrote, bit for bit", "[image][pfm]") {
  ScratchDir dir;
  const std::string path = dir.file("a.pfm");
  const clrt::FloatImage image{
      2, 2, {1.0f, -2.5f, 1e30f, 0.1f, -0.0f, 3e-40f, 65504.0f, 1e-7f, 7.0f, 0.5f, 0.25f, -1e9f}};
  clrt::write_image(path, image);
  const clrt::FloatImage back = clrt::read_pfm(path);
  CHECK(back.width == 2);
  CHECK(back.height == 2);
  CHECK_FALSE(back.placement);
  REQUIRE(back.rgb.size() == image.rgb.size());
  CHECK(std::memcmp(back.rgb.data(), image.rgb.data(), 4 * image.rgb.size()) == 0);
}

TEST_CASE("PFM reader takes big-endian files, grey Pf, and multiplies by |scale|",
          "[image][pfm]") {
  ScratchDir dir;
  const std::string path = dir.file("in.pfm");
  SECTION("big-endian colour, scale 2: every value doubled, bottom row first") {
    // 1.5 = 3fc00000, -4 = c0800000, 0.25 = 3e800000; rows: bottom (1.5, -4, 0.25), top (0, 0, 1)
    write_bytes(path, concat({bytes_of("PF\n1 2\n2.0\n"),
                              {0x3f, 0xc0, 0, 0, 0xc0, 0x80, 0, 0, 0x3e, 0x80, 0, 0},
                              {0, 0, 0, 0, 0, 0, 0, 0, 0x3f, 0x80, 0, 0}}));
    const clrt::FloatImage image = clrt::read_pfm(path);
    CHECK(image.rgb == std::vector<float>{0.0f, 0.0f, 2.0f, 3.0f, -8.0f, 0.5f});
  }
  SECTION("grey little-endian: each value goes to R, G and B") {
    write_bytes(path, concat({bytes_of("Pf\n2 1\n-1\n"), {0, 0, 0x80, 0x3f, 0, 0, 0, 0x40}}));
    CHECK(clrt::read_pfm(path).rgb == std::vector<float>{1, 1, 1, 2, 2, 2});
    CHECK(clrt::info_text(clrt::read_image_info(path)) ==
          "format: PFM\nwidth: 2\nheight: 1\nframes: 1\nchannels: grey\nsamples: 32-bit float\n"
          "placement: none (PFM cannot record one)\nbyte order: little-endian\nscale: -1\n");
  }
}

TEST_CASE("PFM reader rejects malformed files, naming them", "[image][pfm]") {
  ScratchDir dir;
  const std::string path = dir.file("in.pfm");
  const auto rejects = [&](const Bytes& bytes, const std::string& reason) {
    write_bytes(path, bytes);
    CHECK_THROWS_WITH(clrt::read_pfm(path), Contains(path) && Contains(reason));
  };
  const Bytes pixel(12, 0);
  rejects(concat({bytes_of("PF\n1 1\n-1.0\n"), Bytes(11, 0)}), "truncated");
  rejects(concat({bytes_of("PF\n1 1\n-1.0\n"), Bytes(13, 0)}), "extra data");
  rejects(concat({bytes_of("PF\n1 1\nabc\n"), pixel}), "\"abc\" is not a finite non-zero");
  rejects(concat({bytes_of("PF\n1 1\n0.0\n"), pixel}), "non-zero");
  rejects(concat({bytes_of("PF\n1 1\ninf\n"), pixel}), "finite");
  rejects(concat({bytes_of("P6\n1 1\n-1.0\n"), pixel}), "the file holds a PPM image; name it .ppm");
  rejects(concat({bytes_of("PX\n1 1\n-1.0\n"), pixel}), "PF or Pf");
  rejects(bytes_of("PF\n2147483647 2147483647\n-1\n"),
          "the PFM's 2147483647x2147483647 pixels are more than clrt reads");
  rejects(bytes_of("PF\n65536 4096\n-1\n"), "truncated");  // 2^28 pixels: within the limits
}
