#include "image/stitch.hpp"

#include <catch2/catch.hpp>

using clrt::AnyImage;
using clrt::FloatImage;
using clrt::Placement;
using clrt::Rgba8Image;
using clrt::TileImage;
using Catch::Matchers::Contains;
using Catch::Matchers::Equals;

namespace {

constexpr int kWidth = 7, kHeight = 5;

// Every sample different: pixel (x, y) channel c holds x + 10 y + 100 c.
float sample(int x, int y, int c) { return static_cast<float>(x + 10 * y + 100 * c); }

FloatImage full_image() {
  std::vector<float> rgb;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) rgb.push_back(sample(x, y, c));
  return FloatImage(kWidth, kHeight, rgb);
}

// The tile [x0, x1) x [y0, y1) of full_image(), computed from sample() on its own.
TileImage tile(const std::string& name, int x0, int x1, int y0, int y1) {
  std::vector<float> rgb;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) rgb.push_back(sample(x, y, c));
  return {name, FloatImage(x1 - x0, y1 - y0, rgb, Placement{x0, y0, kWidth, kHeight})};
}

std::string stitch_error(const std::vector<TileImage>& tiles) {
  try {
    clrt::stitch_tiles(tiles);
  } catch (const clrt::ImageError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("tiles of uneven sizes, in any order, stitch to the full image", "[image][stitch]") {
  const std::vector<TileImage> tiles{tile("d", 3, 7, 2, 5), tile("a", 0, 3, 0, 2), tile("c", 0, 3, 2, 5),
                                tile("b", 3, 7, 0, 2)};
  const AnyImage stitched = clrt::stitch_tiles(tiles);
  REQUIRE(std::holds_alternative<FloatImage>(stitched));
  const FloatImage& image = std::get<FloatImage>(stitched);
  CHECK(image.width == kWidth);
  CHECK(image.height == kHeight);
  CHECK_FALSE(image.placement);
  CHECK(image.rgb == full_image().rgb);

  const std::vector<TileImage> rows{tile("r0", 0, 7, 0, 1), tile("r1", 0, 7, 1, 4), tile("r2", 0, 7, 4, 5)};
  CHECK(std::get<FloatImage>(clrt::stitch_tiles(rows)).rgb == full_image().rgb);
  const std::vector<TileImage> pixels{tile("p", 0, 1, 0, 1), tile("right", 1, 7, 0, 1),
                                 tile("below", 0, 7, 1, 5)};
  CHECK(std::get<FloatImage>(clrt::stitch_tiles(pixels)).rgb == full_image().rgb);
}

TEST_CASE("8-bit tiles stitch to 8-bit, and a float tile among them makes the whole float",
          "[image][stitch]") {
  const Rgba8Image left(1, 1, {{10, 20, 30, 40}}, Placement{0, 0, 2, 1});
  const Rgba8Image right(1, 1, {{50, 60, 70, 255}}, Placement{1, 0, 2, 1});
  const AnyImage eight = clrt::stitch_tiles({{"l", left}, {"r", right}});
  CHECK(std::get<Rgba8Image>(eight).frames ==
        std::vector<std::vector<std::uint8_t>>{{10, 20, 30, 40, 50, 60, 70, 255}});
  const FloatImage right_float(1, 1, {0.5f, 2.0f, -1.0f}, Placement{1, 0, 2, 1});
  const AnyImage mixed = clrt::stitch_tiles({{"l", left}, {"r", right_float}});
  CHECK(std::get<FloatImage>(mixed).rgb ==
        std::vector<float>{10 / 255.0f, 20 / 255.0f, 30 / 255.0f, 0.5f, 2.0f, -1.0f});
}

TEST_CASE("an overlap names both tiles and the pixels they share", "[image][stitch]") {
  CHECK_THAT(stitch_error({tile("a", 0, 4, 0, 5), tile("b", 3, 7, 1, 5), tile("c", 4, 7, 0, 1)}),
             Equals("tiles a and b overlap: both cover pixels x [3, 4) y [1, 5)"));
  CHECK_THAT(stitch_error({tile("a", 0, 7, 0, 5), tile("again", 0, 7, 0, 5)}),
             Equals("tiles a and again overlap: both cover pixels x [0, 7) y [0, 5)"));
}

TEST_CASE("a gap names the pixels no tile covers", "[image][stitch]") {
  CHECK_THAT(stitch_error({tile("a", 0, 3, 0, 2), tile("b", 3, 7, 0, 2), tile("c", 0, 3, 2, 5)}),
             Equals("the tiles leave 12 of the 7x5 frame's pixels uncovered: x [3, 7) y [2, 5)"));
  CHECK_THAT(stitch_error({tile("a", 1, 6, 1, 4)}),
             Equals("the tiles leave 20 of the 7x5 frame's pixels uncovered: x [0, 7) y [0, 1), "
                    "x [0, 1) y [1, 4), x [6, 7) y [1, 4), x [0, 7) y [4, 5)"));
  CHECK_THAT(stitch_error({tile("a", 0, 1, 0, 1), tile("b", 2, 3, 0, 1), tile("c", 4, 5, 0, 1),
                           tile("d", 6, 7, 0, 1), tile("e", 0, 7, 2, 5), tile("f", 3, 4, 1, 2)}),
             Equals("the tiles leave 9 of the 7x5 frame's pixels uncovered: x [1, 2) y [0, 1), "
                    "x [3, 4) y [0, 1), x [5, 6) y [0, 1), x [0, 3) y [1, 2) and 1 more"));
}

TEST_CASE("tiles must share one full frame, have one frame each, and be given", "[image][stitch]") {
  TileImage other = tile("other", 3, 7, 0, 5);
  std::get<FloatImage>(other.image).placement = Placement{3, 0, 8, 5};
  CHECK_THAT(stitch_error({tile("a", 0, 3, 0, 5), other}),
             Equals("other belongs to a 8x5 frame, a to a 7x5 one"));
  const Rgba8Image animation(1, 1, {{1, 2, 3, 4}, {5, 6, 7, 8}});
  CHECK_THAT(stitch_error({{"anim", animation}}), Contains("anim: a tile has one frame"));
  CHECK_THAT(stitch_error({}), Equals("no tiles to stitch"));
  const FloatImage whole(2, 1, {1, 2, 3, 4, 5, 6});
  CHECK(std::get<FloatImage>(clrt::stitch_tiles({{"whole", whole}})).rgb == whole.rgb);
}
