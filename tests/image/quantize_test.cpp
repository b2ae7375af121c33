#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "image/image.hpp"

using clrt::FloatImage;
using clrt::ImageError;

namespace {

// The red channel of a 1x1 image holding `value`, quantised.
int quantized_red(float value) {
  FloatImage image{1, 1, {value, 0.0f, 0.0f}};
  return clrt::quantize(image).frames.at(0).at(0);
}

}  // namespace

TEST_CASE("quantize rounds value * 255 to nearest after clamping to [0, 1]", "[image][quantize]") {
  CHECK(quantized_red(0.0f) == 0);
  CHECK(quantized_red(1.0f) == 255);
  CHECK(quantized_red(0.5f) == 128);   // 127.5: halfway rounds up
  CHECK(quantized_red(0.25f) == 64);   // 63.75
  CHECK(quantized_red(0.2f) == 51);    // 51.000001
  CHECK(quantized_red(0.1f) == 26);    // 0.1f is 0.10000000149, so 25.50000038
  CHECK(quantized_red(0.0019f) == 0);  // 0.48
  CHECK(quantized_red(0.0021f) == 1);  // 0.54
  CHECK(quantized_red(-0.3f) == 0);
  CHECK(quantized_red(1.7f) == 255);
}

TEST_CASE("quantize maps NaN to 0 and infinities to the ends", "[image][quantize]") {
  CHECK(quantized_red(std::numeric_limits<float>::quiet_NaN()) == 0);
  CHECK(quantized_red(std::numeric_limits<float>::infinity()) == 255);
  CHECK(quantized_red(-std::numeric_limits<float>::infinity()) == 0);
}

TEST_CASE("quantize keeps pixel order and makes every pixel opaque", "[image][quantize]") {
  FloatImage image{2, 1, {1.0f, 0.5f, 0.0f, 0.2f, 2.0f, -1.0f}};
  const clrt::Rgba8Image out = clrt::quantize(image);
  CHECK(out.width == 2);
  CHECK(out.height == 1);
  REQUIRE(out.frames.size() == 1);
  CHECK(out.frames[0] == std::vector<std::uint8_t>{255, 128, 0, 255, 51, 255, 0, 255});
}

TEST_CASE("quantize rejects an empty image and a pixel array of the wrong length",
          "[image][quantize]") {
  CHECK_THROWS_AS(clrt::quantize(FloatImage{0, 0, {}}), ImageError);
  CHECK_THROWS_AS(clrt::quantize(FloatImage{2, 1, {0, 0, 0}}), ImageError);
}

// The rows are quantised in vector loops with a scalar remainder: a long, odd row checks every
// lane against values whose byte is known by construction.
TEST_CASE("quantize gives each channel of a long row its own nearest byte", "[image][quantize]") {
  std::vector<float> rgb;
  std::vector<std::uint8_t> expected;
  const auto add = [&](float value, int byte) {
    rgb.push_back(value);
    expected.push_back(static_cast<std::uint8_t>(byte));
  };
  for (int k = 0; k < 255; ++k) {
    add(static_cast<float>(k / 255.0), k);
    add(static_cast<float>((k + 0.49) / 255.0), k);
    add(static_cast<float>((k + 0.51) / 255.0), k + 1);
  }
  add(std::numeric_limits<float>::quiet_NaN(), 0);
  add(-std::numeric_limits<float>::quiet_NaN(), 0);
  add(std::numeric_limits<float>::infinity(), 255);
  add(-0.0f, 0);
  add(3.0f, 255);
  add(-2.0f, 0);
  const int width = static_cast<int>(rgb.size() / 3);  // 257 pixels
  const std::vector<std::uint8_t> rgba = clrt::quantize(FloatImage{width, 1, rgb}).frames.at(0);
  REQUIRE(rgba.size() == 4u * static_cast<std::size_t>(width));
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO("channel " << i << " value " << rgb[i]);
    CHECK(rgba[i + i / 3] == expected[i]);
  }
}
