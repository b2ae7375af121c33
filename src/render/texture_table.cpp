#include "render/texture_table.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "math/parallel_for.hpp"
#include "scene/scene_image.hpp"

namespace clrt {
namespace {

using Rgb = std::array<double, 3>;

constexpr std::size_t kRowsPerTask = 64;  // small images take one task

// One mip level in linear values, rows from t = 0 (the image's bottom row) up.
struct Level {
  std::size_t width = 0, height = 0;
  std::vector<Rgb> texels;
};

Level first_level(const TextureImage& image) {
  Level level;
  level.width = static_cast<std::size_t>(image.width);
  level.height = static_cast<std::size_t>(image.height);
  level.texels.resize(level.width * level.height);
  parallel_for(level.height, kRowsPerTask, [&](std::size_t y) {
    for (std::size_t x = 0; x < level.width; ++x) {
      const std::size_t from = 3 * ((level.height - 1 - y) * level.width + x);
      Rgb& t = level.texels[y * level.width + x];
      for (std::size_t c = 0; c < 3; ++c)
        t[c] = image.linear ? image.rgb[from + c] : srgb_to_linear(image.srgb[from + c]);
    }
  });
  return level;
}

Level next_level(const Level& fine) {
  Level coarse;
  coarse.width = std::max<std::size_t>(fine.width / 2, 1);
  coarse.height = std::max<std::size_t>(fine.height / 2, 1);
  coarse.texels.resize(coarse.width * coarse.height);
  parallel_for(coarse.height, kRowsPerTask, [&](std::size_t y) {
    for (std::size_t x = 0; x < coarse.width; ++x) {
      const std::size_t xs[2] = {2 * x, std::min(2 * x + 1, fine.width - 1)};
      const std::size_t ys[2] = {2 * y, std::min(2 * y + 1, fine.height - 1)};
      Rgb sum{0, 0, 0};
      for (std::size_t fy : ys)
        for (std::size_t fx : xs)
          for (std::size_t c = 0; c < 3; ++c) sum[c] += fine.texels[fy * fine.width + fx][c];
      for (std::size_t c = 0; c < 3; ++c) coarse.texels[y * coarse.width + x][c] = sum[c] / 4;
    }
  });
  return coarse;
}

// The sRGB code whose linear value is nearest `value`.
std::uint32_t nearest_code(double value) {
  const std::array<float, 256>& v = srgb_linear_values();
  const auto above = std::lower_bound(v.begin(), v.end(), value);
  if (above == v.end()) return 255;
  const auto code = static_cast<std::uint32_t>(above - v.begin());
  if (code > 0 && value - v[code - 1] <= *above - value) return code - 1;
  return code;
}

dev::u32 float_word(double value) {
  const float f = static_cast<float>(value);
  dev::u32 w;
  std::memcpy(&w, &f, sizeof w);
  return w;
}

void append_level(const Level& level, bool linear, DeviceTable<dev::u32>& words) {
  const std::size_t first = words.size(), per_texel = linear ? 3 : 1;
  words.resize(first + per_texel * level.texels.size());
  parallel_for(level.texels.size(), kRowsPerTask * level.width, [&](std::size_t i) {
    const Rgb& t = level.texels[i];
    dev::u32* out = &words[first + per_texel * i];
    if (linear) {
      for (std::size_t c = 0; c < 3; ++c) out[c] = float_word(t[c]);
    } else {
      *out = nearest_code(t[0]) | nearest_code(t[1]) << 8 | nearest_code(t[2]) << 16;
    }
  });
}

}  // namespace

TextureTable make_texture_table(const Scene& scene) {
  TextureTable table;
  table.records.push_back(dev::Texture{});
  static_assert(CLRT_SRGB_TABLE_WORDS == 256);
  for (float value : srgb_linear_values()) table.texels.push_back(float_word(value));
  struct Placed {
    dev::u32 first_word = 0, levels = 0;
  };
  std::vector<Placed> placed(scene.texture_images.size());
  std::vector<bool> used(scene.texture_images.size(), false);
  for (const TextureSpec& t : scene.textures)
    if (t.kind == TextureSpec::Kind::Image) used.at(static_cast<std::size_t>(t.image)) = true;
  for (std::size_t i = 0; i < scene.texture_images.size(); ++i) {
    if (!used[i]) continue;
    const TextureImage& image = scene.texture_images[i];
    placed[i].first_word = static_cast<dev::u32>(table.texels.size());
    Level level = first_level(image);
    for (;;) {
      append_level(level, image.linear, table.texels);
      if (table.texels.size() > UINT32_MAX)
        throw std::runtime_error("the scene's textures take more than 2^32 texel words");
      ++placed[i].levels;
      if (level.width == 1 && level.height == 1) break;
      level = next_level(level);
    }
  }
  for (const TextureSpec& t : scene.textures) {
    dev::Texture d{};
    d.color0 = {static_cast<float>(t.color0.x), static_cast<float>(t.color0.y), static_cast<float>(t.color0.z), 0};
    d.color1 = {static_cast<float>(t.color1.x), static_cast<float>(t.color1.y), static_cast<float>(t.color1.z), 0};
    for (int k = 0; k < 2; ++k) {
      d.scale[k] = static_cast<float>(t.scale[k]);
      d.offset[k] = static_cast<float>(t.offset[k]);
    }
    d.wrap = t.clamp ? CLRT_WRAP_CLAMP : CLRT_WRAP_REPEAT;
    d.octaves = static_cast<dev::u32>(t.octaves);
    switch (t.kind) {
      case TextureSpec::Kind::Checker: d.kind = CLRT_TEXTURE_CHECKER; break;
      case TextureSpec::Kind::Noise: d.kind = CLRT_TEXTURE_NOISE; break;
      case TextureSpec::Kind::Image: {
        const auto image = static_cast<std::size_t>(t.image);
        const TextureImage& source = scene.texture_images.at(image);
        d.kind = CLRT_TEXTURE_IMAGE;
        d.width = static_cast<dev::u32>(source.width);
        d.height = static_cast<dev::u32>(source.height);
        d.levels = placed[image].levels;
        d.first_word = placed[image].first_word;
        d.texel_format = source.linear ? CLRT_TEXELS_FLOAT : CLRT_TEXELS_SRGB8;
        break;
      }
    }
    table.records.push_back(d);
  }
  return table;
}

}  // namespace clrt
