#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "test_files.hpp"

using namespace clrt::test;

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
