#include "image/compare.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using clrt::FloatImage;
using clrt::ImageDifference;
using clrt::Rgba8Image;
using Catch::Matchers::Contains;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

const Rgba8Image kA(2, 1, {{10, 20, 30, 255, 100, 100, 100, 255}});
// Green of pixel 0 is 2 higher, blue of pixel 1 is 5 lower; the alphas differ but do not count.
const Rgba8Image kB(2, 1, {{10, 22, 30, 0, 100, 100, 95, 255}});

}  // namespace

TEST_CASE("8-bit comparison: steps of 1/255, PSNR against 255", "[image][compare]") {
  const ImageDifference d = clrt::compare_images(kA, kB, 0);
  CHECK_FALSE(d.floats);
  CHECK(d.pixels == 2);
  CHECK(d.differing == 2);
  CHECK(d.largest == 5);
  // mean square (4 + 25) / 6; 10 log10(255^2 * 6 / 29)
  CHECK(d.psnr == Approx(41.28833613352598).epsilon(1e-12));
  CHECK(d.difference.rgb == std::vector<float>{0, 0.4f, 0, 0, 0, 1});
  CHECK(clrt::compare_images(kA, kB, 2).differing == 1);
  CHECK(clrt::compare_images(kA, kB, 4.99).differing == 1);
  CHECK(clrt::compare_images(kA, kB, 5).differing == 0);
}

TEST_CASE("identical images: no difference, infinite PSNR, a black difference image",
          "[image][compare]") {
  const ImageDifference d = clrt::compare_images(kA, kA, 0);
  CHECK(d.differing == 0);
  CHECK(d.largest == 0);
  CHECK(std::isinf(d.psnr));
  CHECK(d.psnr > 0);
  CHECK(d.difference.rgb == std::vector<float>(6, 0.0f));
}

TEST_CASE("float comparison: linear units, PSNR against 1, equal bits never differ",
          "[image][compare]") {
  const FloatImage a(2, 1, {0, 0, 0, 1, kNaN, 3});
  const FloatImage b(2, 1, {0, 0, 0.001f, 1, kNaN, 3});
  const ImageDifference d = clrt::compare_images(a, b, 0);
  CHECK(d.floats);
  CHECK(d.differing == 1);
  CHECK(d.largest == 0.0010000000474974513);  // the float nearest 0.001, as a double
  CHECK(d.psnr == Approx(67.78151209127883).epsilon(1e-12));
  CHECK(clrt::compare_images(a, b, 0.001).differing == 1);  // 0.001f is a little above 0.001
  CHECK(clrt::compare_images(a, b, 0.0011).differing == 0);

  const FloatImage c(2, 1, {0.5f, 0, 0, 1, 2, kInf});
  const ImageDifference e = clrt::compare_images(a, c, 0);
  CHECK(std::isinf(e.largest));  // NaN against 2, 3 against inf
  CHECK(std::isinf(e.psnr));
  CHECK(e.psnr < 0);
  CHECK(e.difference.rgb == std::vector<float>{1, 0, 0, 0, 1, 1});
}

TEST_CASE("a float image against an 8-bit one is quantised as clrt's PNG output is",
          "[image][compare]") {
  const FloatImage rendered(1, 1, {0.5f, 0.2f, 1.7f});
  const Rgba8Image png(1, 1, {{128, 51, 255, 255}});
  const ImageDifference d = clrt::compare_images(rendered, png, 0);
  CHECK_FALSE(d.floats);
  CHECK(d.largest == 0);
  const ImageDifference off = clrt::compare_images(png, FloatImage(1, 1, {0.5f, 0.2f, 0.99f}), 0);
  CHECK(off.largest == 3);  // 0.99 * 255 = 252.45 -> 252
}

TEST_CASE("images of different sizes or with several frames are not compared",
          "[image][compare]") {
  CHECK_THROWS_WITH(clrt::compare_images(kA, Rgba8Image(1, 2, {std::vector<std::uint8_t>(8)}), 0),
                    Contains("cannot compare a 2x1 image with a 1x2 one"));
  const Rgba8Image animation(2, 1, {kA.frames[0], kA.frames[0]});
  CHECK_THROWS_WITH(clrt::compare_images(kA, animation, 0),
                    Contains("image B") && Contains("2 frames"));
}
