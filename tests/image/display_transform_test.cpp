// The display transform every 8-bit output of a float image goes through: exposure, tone curve,
// encoding, quantisation, each against values worked out by hand, and the writers using it.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "image/display_transform.hpp"
#include "image/image.hpp"
#include "test_files.hpp"

using clrt::DisplayTransform;
using clrt::FloatImage;
using clrt::ToneCurve;

namespace {

DisplayTransform srgb() {
  DisplayTransform display;
  display.srgb = true;
  return display;
}

DisplayTransform filmic() {
  DisplayTransform display;
  display.curve = ToneCurve::Filmic;
  return display;
}

DisplayTransform exposed(double stops) {
  DisplayTransform display;
  display.exposure = stops;
  return display;
}

}  // namespace

TEST_CASE("sRGB's encoding at known points", "[image][display]") {
  CHECK(clrt::srgb_encode(0) == 0);
  CHECK(clrt::srgb_encode(0.0031308) == Approx(0.040449936).epsilon(1e-12));  // 12.92 v to its end
  CHECK(clrt::srgb_encode(0.0031309) == Approx(0.0404512).epsilon(1e-5));  // the power's start
  CHECK(clrt::srgb_encode(0.5) == Approx(0.7353569831).epsilon(1e-9));
  CHECK(clrt::srgb_encode(1) == Approx(1).epsilon(1e-15));
  CHECK(clrt::display_byte(0.5f, srgb()) == 188);   // 0.7353569 * 255 = 187.52
  CHECK(clrt::display_byte(0.0f, srgb()) == 0);
  CHECK(clrt::display_byte(1.0f, srgb()) == 255);
  CHECK(clrt::display_byte(0.001f, srgb()) == 3);   // 12.92 * 0.001 * 255 = 3.29
  CHECK(clrt::display_byte(0.2f, srgb()) == 124);   // 0.4845292 * 255 = 123.56
}

TEST_CASE("the filmic curve is Narkowicz's fit, clamped to [0, 1]", "[image][display]") {
  for (double x : {0.0, 0.01, 0.18, 0.5, 1.0, 2.0, 4.0}) {
    INFO(x);
    CHECK(clrt::filmic_curve(x) ==
          Approx(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)).epsilon(1e-15));
  }
  CHECK(clrt::filmic_curve(1) == Approx(0.8037975).epsilon(1e-7));  // 2.54 / 3.16
  CHECK(clrt::filmic_curve(10) == 1);                                // above 1 past 7.25
  CHECK(clrt::filmic_curve(std::numeric_limits<double>::infinity()) == 1);
  CHECK(clrt::filmic_curve(1e300) == 1);
  CHECK(clrt::display_byte(1.0f, filmic()) == 205);  // 0.8037975 * 255 = 204.97
  CHECK(clrt::display_byte(100.0f, filmic()) == 255);
}

TEST_CASE("exposure doubles the value per stop before the curve", "[image][display]") {
  CHECK(clrt::display_value(0.25, exposed(1)) == 0.5);
  CHECK(clrt::display_value(0.25, exposed(2)) == 1);
  CHECK(clrt::display_value(0.25, exposed(-1)) == 0.125);
  CHECK(clrt::display_value(3, exposed(0)) == 1);  // clamped
  CHECK(clrt::display_byte(0.25f, exposed(1)) == 128);
  DisplayTransform both = srgb();
  both.exposure = 1;
  CHECK(clrt::display_value(0.25, both) == clrt::srgb_encode(0.5));
  both.curve = ToneCurve::Filmic;
  CHECK(clrt::display_value(0.25, both) == clrt::srgb_encode(clrt::filmic_curve(0.5)));
}

TEST_CASE("NaN, negatives and infinities through the display transform", "[image][display]") {
  for (const DisplayTransform& display : {srgb(), filmic(), exposed(3)}) {
    CHECK(clrt::display_byte(std::numeric_limits<float>::quiet_NaN(), display) == 0);
    CHECK(clrt::display_byte(-0.5f, display) == 0);
    CHECK(clrt::display_byte(-std::numeric_limits<float>::infinity(), display) == 0);
    CHECK(clrt::display_byte(std::numeric_limits<float>::infinity(), display) == 255);
  }
}

TEST_CASE("the identity transform is the contract's quantisation", "[image][display]") {
  CHECK(DisplayTransform{}.identity());
  CHECK_FALSE(srgb().identity());
  CHECK_FALSE(filmic().identity());
  CHECK_FALSE(exposed(0.5).identity());
  const FloatImage image{3, 1, {0.5f, 0.25f, 0.1f, 2.0f, -1.0f, 0.0019f, 0.0021f, 0.2f, 1.0f}};
  CHECK(clrt::quantize(image, {}).frames == clrt::quantize(image).frames);
  const std::vector<std::uint8_t> expected{128, 64, 26, 255, 255, 0, 0, 255, 1, 51, 255, 255};
  CHECK(clrt::quantize(image).frames.at(0) == expected);
}

TEST_CASE("8-bit writers put a float image through WriteOptions::display, float ones do not",
          "[image][display]") {
  clrt::test::ScratchDir dir;
  const FloatImage image{2, 1, {0.5f, 0.2f, 0.001f, 1.0f, 0.0f, 0.25f}};
  clrt::WriteOptions options;
  options.display = srgb();
  const std::vector<std::uint8_t> encoded{188, 124, 3, 255, 255, 0, 137, 255};
  for (const char* name : {"a.png", "a.ppm", "a.fsf"}) {
    INFO(name);
    clrt::write_image(dir.file(name), image, options);
    const clrt::Rgba8Image read = clrt::read_image(dir.file(name));
    CHECK(read.frames.at(0) == encoded);
  }
  CHECK(clrt::quantize(image, srgb()).frames.at(0) == encoded);
  clrt::write_image(dir.file("a.pfm"), image, options);
  CHECK(clrt::read_pfm(dir.file("a.pfm")).rgb == image.rgb);
}
