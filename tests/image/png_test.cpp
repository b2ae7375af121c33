#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "test_files.hpp"

using clrt::ImageError;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

constexpr std::size_t kIhdrBitDepth = 24,
                      kIhdrColourType = 25;  // after signature, length, "IHDR", size
constexpr int kColourRgb = 2, kColourRgba = 6;

std::string fixture(const std::string& name) {
  return std::string(CLRT_SOURCE_DIR) + "/tests/image/data/" + name;
}

Rgba8Image read_fixture(const std::string& name) { return clrt::read_png(fixture(name)); }

}  // namespace

TEST_CASE("PNG round trips translucent RGBA exactly", "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("a.png");
  const Rgba8Image image{3, 2, {{0,  0,  0,  0,  255, 128, 1,  1,   9, 99, 199, 254,  //
                                 17, 34, 51, 68, 200, 100, 50, 255, 3, 2,  1,   127}}};
  clrt::write_image(path, image);
  const Bytes file = read_bytes(path);
  REQUIRE(file.size() > kIhdrColourType);
  CHECK(file[kIhdrBitDepth] == 8);
  CHECK(file[kIhdrColourType] == kColourRgba);
  const Rgba8Image back = clrt::read_png(path);
  CHECK(back.width == 3);
  CHECK(back.height == 2);
  CHECK(back.frames == image.frames);
}

TEST_CASE("PNG of an opaque image is 8-bit RGB and reads back with alpha 255", "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("rendered.PNG");  // the extension is matched case-insensitively
  clrt::write_image(path, clrt::FloatImage{2, 1, {0.5f, 1.5f, -1.0f, 0.2f, 0.0f, 1.0f}});
  const Bytes file = read_bytes(path);
  REQUIRE(file.size() > kIhdrColourType);
  CHECK(Bytes(file.begin(), file.begin() + 8) ==
        Bytes{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
  CHECK(file[kIhdrBitDepth] == 8);
  CHECK(file[kIhdrColourType] == kColourRgb);
  CHECK(clrt::read_png(path).frames == std::vector<Bytes>{{128, 255, 0, 255, 51, 0, 255, 255}});
}

TEST_CASE("PNG writer takes frame 0 of an animation", "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("anim.png");
  clrt::write_image(path, Rgba8Image{1, 1, {{1, 2, 3, 255}, {4, 5, 6, 255}}});
  CHECK(clrt::read_png(path).frames == std::vector<Bytes>{{1, 2, 3, 255}});
}

TEST_CASE("PNG reader converts other bit depths and colour types to 8-bit RGBA", "[image][png]") {
  SECTION("16-bit RGB: each sample becomes round(v * 255 / 65535)") {
    const Rgba8Image image = read_fixture("rgb16.png");
    CHECK(image.width == 2);
    CHECK(image.height == 1);
    // 0x1234 = 4660 -> 18.13; 0x8080 -> 128; 0x12c0 = 4800 -> 18.68; 0xfeff -> 254
    CHECK(image.frames == std::vector<Bytes>{{18, 128, 255, 255, 0, 19, 254, 255}});
  }
  SECTION("2-bit palette with tRNS transparency") {
    CHECK(read_fixture("palette2.png").frames ==
          std::vector<Bytes>{{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 10, 20, 30, 255}});
  }
  SECTION("1-bit grey") {
    const Rgba8Image image = read_fixture("gray1.png");
    CHECK(image.width == 8);
    CHECK(image.frames == std::vector<Bytes>{{255, 255, 255, 255, 0,   0,   0,   255,  //
                                              255, 255, 255, 255, 255, 255, 255, 255,  //
                                              0,   0,   0,   255, 0,   0,   0,   255,  //
                                              0,   0,   0,   255, 255, 255, 255, 255}});
  }
  SECTION("8-bit grey with alpha") {
    CHECK(read_fixture("gray_alpha8.png").frames ==
          std::vector<Bytes>{{100, 100, 100, 50, 200, 200, 200, 255}});
  }
}

TEST_CASE("PNG reader rejects a file that is not a PNG or is cut short, naming it",
          "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("bad.png");
  write_bytes(path, bytes_of("P6\n1 1\n255\nabc"));
  CHECK_THROWS_WITH(clrt::read_png(path), Contains(path));

  const Bytes good = read_bytes(fixture("rgb16.png"));
  write_bytes(path, Bytes(good.begin(), good.begin() + 50));
  CHECK_THROWS_WITH(clrt::read_png(path), Contains(path));
  CHECK_THROWS_AS(clrt::read_png(dir.file("missing.png")), ImageError);
}
