#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include "image/image.hpp"
#include "test_files.hpp"

using clrt::FloatImage;
using clrt::ImageError;
using clrt::PngEncoding;
using clrt::PngFilters;
using clrt::PngStrategy;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

constexpr PngFilters kAllFilters[] = {PngFilters::None,    PngFilters::Sub,
                                      PngFilters::Up,      PngFilters::Average,
                                      PngFilters::Paeth,   PngFilters::Adaptive};
constexpr PngStrategy kAllStrategies[] = {PngStrategy::Default, PngStrategy::Filtered,
                                          PngStrategy::Rle, PngStrategy::HuffmanOnly};

// Smooth gradients, runs and a noisy corner, odd sizes: something for every filter to predict
// and something for it to miss.
FloatImage test_render(int width, int height) {
  std::vector<float> rgb;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool noisy = x > width / 2 && y > height / 2;
      rgb.push_back(static_cast<float>(x) / static_cast<float>(width));
      rgb.push_back(noisy ? static_cast<float>((x * 7919 + y * 104729) % 256) / 255.0f : 0.25f);
      rgb.push_back(static_cast<float>(y % 5) * 0.3f);  // above 1 on some rows: clamped
    }
  return {width, height, std::move(rgb)};
}

Rgba8Image translucent(int width, int height) {
  std::vector<std::uint8_t> rgba;
  for (int i = 0; i < width * height; ++i)
    for (int c = 0; c < 4; ++c) rgba.push_back(static_cast<std::uint8_t>((i * (c + 3) * 37) & 255));
  return {width, height, {std::move(rgba)}};
}

std::string write_with(const ScratchDir& dir, const std::string& name, const FloatImage& image,
                       const PngEncoding& encoding) {
  const std::string path = dir.file(name);
  clrt::write_image(path, image, {clrt::ExrPixel::Half, encoding});
  return path;
}

}  // namespace

TEST_CASE("every PNG filter, strategy and level stores the same pixels", "[image][png]") {
  ScratchDir dir;
  const FloatImage render = test_render(37, 23);
  const Rgba8Image alpha = translucent(19, 11);
  const auto expected = clrt::quantize(render).frames;
  for (const PngFilters filters : kAllFilters)
    for (const PngStrategy strategy : kAllStrategies)
      for (const int level : {0, 1, 9}) {
        const PngEncoding encoding{level, filters, strategy};
        INFO(clrt::describe(encoding));
        CHECK(clrt::read_png(write_with(dir, "rgb.png", render, encoding)).frames == expected);
        const std::string path = dir.file("rgba.png");
        clrt::write_image(path, alpha, {clrt::ExrPixel::Half, encoding});
        CHECK(clrt::read_png(path).frames == alpha.frames);
      }
}

// The rows are compressed in bands of at least 16 rows on every core; the bands must join into
// one stream whatever their number, including a band of a single row.
TEST_CASE("PNG images of one to many bands store their pixels", "[image][png]") {
  ScratchDir dir;
  for (const int height : {1, 15, 16, 17, 33, 300, 1000}) {
    INFO("height " << height);
    const FloatImage render = test_render(5, height);
    const std::string path = write_with(dir, "tall.png", render, {});
    CHECK(clrt::read_png(path).frames == clrt::quantize(render).frames);
  }
}

TEST_CASE("the PNG settings reach the encoder", "[image][png]") {
  ScratchDir dir;
  const FloatImage render = test_render(64, 48);
  const auto size = [&](const PngEncoding& encoding) {
    return std::filesystem::file_size(write_with(dir, "a.png", render, encoding));
  };
  // Level 0 stores the filtered rows: more bytes than the raw samples. Compression at any level
  // stores fewer.
  const std::uintmax_t stored = size({0, PngFilters::None, PngStrategy::Default});
  CHECK(stored > 3u * 64 * 48);
  CHECK(size({9, PngFilters::Adaptive, PngStrategy::Default}) < stored / 2);
  // Huffman codes alone cannot use the repeated rows and runs that matches can.
  CHECK(size({1, PngFilters::Up, PngStrategy::HuffmanOnly}) >
        size({1, PngFilters::Up, PngStrategy::Default}));
}

TEST_CASE("a PNG level outside 0-9 is refused before any file exists", "[image][png]") {
  ScratchDir dir;
  for (const int level : {-1, 10}) {
    const std::string path = dir.file("never.png");
    CHECK_THROWS_WITH(write_with(dir, "never.png", test_render(2, 2),
                                 {level, PngFilters::Sub, PngStrategy::Rle}),
                      Contains(path) && Contains("compression level " + std::to_string(level)));
    CHECK(std::filesystem::is_empty(dir.path()));
  }
  // Other formats ignore the PNG settings.
  CHECK_NOTHROW(clrt::write_image(dir.file("a.ppm"), test_render(2, 2),
                                  {clrt::ExrPixel::Half, {10, PngFilters::Sub, PngStrategy::Rle}}));
}

TEST_CASE("PNG filter and strategy names read back as what they name", "[image][png]") {
  for (const PngFilters filters : kAllFilters)
    CHECK(clrt::png_filters_from_name(clrt::png_filters_name(filters)) == filters);
  for (const PngStrategy strategy : kAllStrategies)
    CHECK(clrt::png_strategy_from_name(clrt::png_strategy_name(strategy)) == strategy);
  CHECK(clrt::png_filters_from_name("paeth") == PngFilters::Paeth);
  CHECK(clrt::png_strategy_from_name("huffman") == PngStrategy::HuffmanOnly);
  CHECK_THROWS_WITH(clrt::png_filters_from_name("Paeth"),
                    Contains("'Paeth'") && Contains("none, sub, up, average, paeth, adaptive"));
  CHECK_THROWS_AS(clrt::png_strategy_from_name("fast"), ImageError);
  CHECK(clrt::describe({2, PngFilters::Up, PngStrategy::Rle}) ==
        "level 2, filters up, strategy rle");
}
