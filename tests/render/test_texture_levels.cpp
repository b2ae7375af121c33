// The texture table's mip levels (render/texture_table.hpp) against a direct computation: every
// level averaged from the whole level before it in double, each 8-bit texel the code found by
// trying all 256. Images tall enough to be made band by band, with partial and odd bands, and
// short ones that are not; on one thread and on many, the same words.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "math/parallel_for.hpp"
#include "render/texture_table.hpp"
#include "scene/scene_image.hpp"

using namespace clrt;

namespace {

using Rgb = std::array<double, 3>;

struct Level {
  std::size_t width, height;
  std::vector<Rgb> texels;  // rows from the image's bottom up
};

std::vector<Level> expected_levels(const TextureImage& image) {
  Level level{static_cast<std::size_t>(image.width), static_cast<std::size_t>(image.height), {}};
  for (std::size_t y = 0; y < level.height; ++y)
    for (std::size_t x = 0; x < level.width; ++x) {
      const std::size_t from = 3 * ((level.height - 1 - y) * level.width + x);
      Rgb t;
      for (std::size_t c = 0; c < 3; ++c)
        t[c] = image.linear ? image.rgb[from + c] : srgb_to_linear(image.srgb[from + c]);
      level.texels.push_back(t);
    }
  std::vector<Level> levels{level};
  while (levels.back().width > 1 || levels.back().height > 1) {
    const Level& f = levels.back();
    Level c{std::max<std::size_t>(f.width / 2, 1), std::max<std::size_t>(f.height / 2, 1), {}};
    for (std::size_t y = 0; y < c.height; ++y)
      for (std::size_t x = 0; x < c.width; ++x) {
        Rgb sum{0, 0, 0};
        for (std::size_t fy : {2 * y, std::min(2 * y + 1, f.height - 1)})
          for (std::size_t fx : {2 * x, std::min(2 * x + 1, f.width - 1)})
            for (std::size_t k = 0; k < 3; ++k) sum[k] += f.texels[fy * f.width + fx][k];
        c.texels.push_back({sum[0] / 4, sum[1] / 4, sum[2] / 4});
      }
    levels.push_back(c);
  }
  return levels;
}

std::uint32_t nearest_by_trying_all(double value) {
  std::uint32_t best = 0;
  for (std::uint32_t code = 1; code < 256; ++code)
    if (std::fabs(srgb_to_linear(static_cast<std::uint8_t>(code)) - value) <
        std::fabs(srgb_to_linear(static_cast<std::uint8_t>(best)) - value))
      best = code;
  return best;
}

std::vector<std::uint32_t> expected_words(const TextureImage& image) {
  std::vector<std::uint32_t> words;
  for (const Level& level : expected_levels(image))
    for (const Rgb& t : level.texels) {
      if (image.linear) {
        for (double v : t) {
          const float f = static_cast<float>(v);
          std::uint32_t w;
          std::memcpy(&w, &f, sizeof w);
          words.push_back(w);
        }
      } else {
        words.push_back(nearest_by_trying_all(t[0]) | nearest_by_trying_all(t[1]) << 8 |
                        nearest_by_trying_all(t[2]) << 16);
      }
    }
  return words;
}

TextureImage random_image(int width, int height, bool linear, unsigned seed) {
  std::mt19937 random(seed);
  TextureImage image;
  image.path = "image" + std::to_string(seed);
  image.width = width;
  image.height = height;
  image.linear = linear;
  const std::size_t values = 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  for (std::size_t i = 0; i < values; ++i) {
    if (linear) image.rgb.push_back(std::uniform_real_distribution<float>(0, 4)(random));
    else image.srgb.push_back(static_cast<std::uint8_t>(random() & 255));
  }
  return image;
}

}  // namespace

TEST_CASE("every mip level is the mean of the one before, however the images are split to be made",
          "[render][texture]") {
  Scene scene;
  // Tall enough for bands (a partial last one, odd sides), then too short for them.
  scene.texture_images = {random_image(70, 150, false, 1), random_image(131, 67, true, 2),
                          random_image(200, 20, false, 3), random_image(64, 64, false, 4),
                          random_image(1, 130, true, 5)};
  for (std::size_t i = 0; i < scene.texture_images.size(); ++i) {
    TextureSpec spec;
    spec.image = static_cast<int>(i);
    scene.textures.push_back(spec);
  }
  parallel_thread_limit = 1;
  const TextureTable one = make_texture_table(scene);
  parallel_thread_limit = 0;
  const TextureTable many = make_texture_table(scene);
  CHECK(std::vector<std::uint32_t>(one.texels.begin(), one.texels.end()) ==
        std::vector<std::uint32_t>(many.texels.begin(), many.texels.end()));
  std::size_t words = CLRT_SRGB_TABLE_WORDS;
  for (std::size_t i = 0; i < scene.texture_images.size(); ++i) {
    const TextureImage& image = scene.texture_images[i];
    INFO(image.width << "x" << image.height << (image.linear ? " float" : " 8-bit"));
    const dev::Texture& record = many.records.at(texture_row(static_cast<int>(i)));
    const std::vector<std::uint32_t> expected = expected_words(image);
    CHECK(record.first_word == words);
    CHECK(record.levels == expected_levels(image).size());
    REQUIRE(words + expected.size() <= many.texels.size());
    CHECK(std::vector<std::uint32_t>(many.texels.begin() + static_cast<std::ptrdiff_t>(words),
                                     many.texels.begin() + static_cast<std::ptrdiff_t>(words + expected.size())) ==
          expected);
    words += expected.size();
  }
  CHECK(many.texels.size() == words);
}
