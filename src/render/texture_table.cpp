#include "render/texture_table.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "math/parallel_for.hpp"
#include "scene/scene_image.hpp"

namespace clrt {
namespace {

using Rgb = std::array<double, 3>;

constexpr std::size_t kRowsPerTask = 64;  // small images take one task
// Levels 0 to kBandLevels are made band by band, each band 2^kBandLevels rows of level 0, so that
// no full-size level of doubles (24 bytes a texel: 6 GiB for a 16384^2 image) is ever held.
constexpr std::size_t kBandLevels = 6;
constexpr std::size_t kBandRows = std::size_t{1} << kBandLevels;

struct Size {
  std::size_t width = 0, height = 0;
};

// Every level's size, from the image's down to 1x1.
std::vector<Size> level_sizes(const TextureImage& image) {
  std::vector<Size> sizes{{static_cast<std::size_t>(image.width), static_cast<std::size_t>(image.height)}};
  while (sizes.back().width > 1 || sizes.back().height > 1)
    sizes.push_back({std::max<std::size_t>(sizes.back().width / 2, 1), std::max<std::size_t>(sizes.back().height / 2, 1)});
  return sizes;
}

// Rows [first, first + count) of one mip level in linear values; rows count from t = 0 (the
// image's bottom row) up.
struct Rows {
  std::size_t width = 0, first = 0, count = 0;
  std::vector<Rgb> texels;
};

// Sizes `rows` for rows [first, end) of `width` texels, keeping its buffer: fresh pages for
// every band cost more system time than the averaging itself.
void size_rows(Rows& rows, std::size_t width, std::size_t first, std::size_t end) {
  rows.width = width;
  rows.first = first;
  rows.count = end > first ? end - first : 0;
  rows.texels.resize(rows.width * rows.count);
}

Rows make_rows(std::size_t width, std::size_t first, std::size_t end) {
  Rows rows;
  size_rows(rows, width, first, end);
  return rows;
}

// Level 0's rows [first, end), from the image, into `rows`.
void source_rows(const TextureImage& image, std::size_t first, std::size_t end, Rows& rows) {
  size_rows(rows, static_cast<std::size_t>(image.width), first, end);
  const auto height = static_cast<std::size_t>(image.height);
  for (std::size_t y = first; y < end; ++y)
    for (std::size_t x = 0; x < rows.width; ++x) {
      const std::size_t from = 3 * ((height - 1 - y) * rows.width + x);
      Rgb& t = rows.texels[(y - first) * rows.width + x];
      for (std::size_t c = 0; c < 3; ++c)
        t[c] = image.linear ? image.rgb[from + c] : srgb_to_linear(image.srgb[from + c]);
    }
}

// The next level's rows [first, end), each texel the mean of a 2x2 block of `fine` (a level
// `fine_height` rows high), which holds the rows they need; into `rows`.
void coarser_rows(const Rows& fine, std::size_t fine_height, Size coarse, std::size_t first, std::size_t end,
                  Rows& rows) {
  size_rows(rows, coarse.width, first, end);
  for (std::size_t y = first; y < end; ++y)
    for (std::size_t x = 0; x < rows.width; ++x) {
      const std::size_t xs[2] = {2 * x, std::min(2 * x + 1, fine.width - 1)};
      const std::size_t ys[2] = {2 * y, std::min(2 * y + 1, fine_height - 1)};
      Rgb sum{0, 0, 0};
      for (std::size_t fy : ys)
        for (std::size_t fx : xs)
          for (std::size_t c = 0; c < 3; ++c) sum[c] += fine.texels[(fy - fine.first) * fine.width + fx][c];
      for (std::size_t c = 0; c < 3; ++c) rows.texels[(y - first) * rows.width + x][c] = sum[c] / 4;
    }
}

// The sRGB code whose linear value is nearest `value` (>= 0), the lower one on a tie. The search
// for the first code not below `value` starts at its bucket's first, a step or two away, rather
// than halving all 256: it ran for a third of a large texture's load.
std::uint32_t nearest_code(double value) {
  constexpr std::size_t kBuckets = 4096;
  const std::array<float, 256>& v = srgb_linear_values();
  static const std::array<std::uint16_t, kBuckets + 1> bucket_start = [&v] {
    std::array<std::uint16_t, kBuckets + 1> starts{};
    for (std::size_t b = 0; b <= kBuckets; ++b)
      starts[b] = static_cast<std::uint16_t>(
          std::lower_bound(v.begin(), v.end(), static_cast<double>(b) / kBuckets) - v.begin());
    return starts;
  }();
  std::size_t code = bucket_start[std::min(kBuckets, static_cast<std::size_t>(value * kBuckets))];
  while (code < v.size() && v[code] < value) ++code;
  if (code == v.size()) return 255;
  if (code > 0 && value - v[code - 1] <= v[code] - value) return static_cast<std::uint32_t>(code - 1);
  return static_cast<std::uint32_t>(code);
}

dev::u32 float_word(double value) {
  const float f = static_cast<float>(value);
  dev::u32 w;
  std::memcpy(&w, &f, sizeof w);
  return w;
}

// Writes `rows` into their level, whose words start at `level`.
void put_rows(const Rows& rows, bool linear, dev::u32* level) {
  const std::size_t per_texel = linear ? 3 : 1;
  dev::u32* out = level + per_texel * rows.first * rows.width;
  for (const Rgb& t : rows.texels) {
    if (linear) {
      for (std::size_t c = 0; c < 3; ++c) *out++ = float_word(t[c]);
    } else {
      *out++ = nearest_code(t[0]) | nearest_code(t[1]) << 8 | nearest_code(t[2]) << 16;
    }
  }
}

// Writes level 0's `rows` of `image`. An 8-bit image's own codes are the nearest to their linear
// values (the table increases strictly), so they are copied rather than searched for.
void put_source_rows(const TextureImage& image, const Rows& rows, dev::u32* level) {
  if (image.linear) return put_rows(rows, true, level);
  const auto height = static_cast<std::size_t>(image.height);
  dev::u32* out = level + rows.first * rows.width;
  for (std::size_t y = rows.first; y < rows.first + rows.count; ++y) {
    const std::uint8_t* in = &image.srgb[3 * (height - 1 - y) * rows.width];
    for (std::size_t x = 0; x < rows.width; ++x, in += 3)
      *out++ = dev::u32{in[0]} | dev::u32{in[1]} << 8 | dev::u32{in[2]} << 16;
  }
}

// One image's levels into `words`, level k at words + starts[k]. Levels are made from the ones
// before in the same order of sums however they are split, so the bands change no bit.
void make_levels(const TextureImage& image, const std::vector<Size>& sizes, const std::vector<std::size_t>& starts,
                 dev::u32* words) {
  // Bands need every level up to kBandLevels halved without clamping: at least kBandRows rows.
  const std::size_t banded = sizes[0].height >= kBandRows ? kBandLevels : 0;
  Rows level;
  if (banded) {
    size_rows(level, sizes[banded].width, 0, sizes[banded].height);
  } else {
    source_rows(image, 0, sizes[0].height, level);
    put_source_rows(image, level, words + starts[0]);
  }
  // Each worker takes every workers-th band, through two buffers of its own.
  const std::size_t bands = banded ? (sizes[0].height + kBandRows - 1) / kBandRows : 0;
  const std::size_t workers = std::min<std::size_t>(parallel_threads(), bands);
  parallel_for(workers, 1, [&](std::size_t worker) {
    Rows fine, coarse;
    for (std::size_t band = worker; band < bands; band += workers) {
      const auto rows_of = [&](std::size_t k) {
        return std::pair{band * kBandRows >> k, std::min(sizes[k].height, (band + 1) * kBandRows >> k)};
      };
      source_rows(image, rows_of(0).first, rows_of(0).second, fine);
      put_source_rows(image, fine, words + starts[0]);
      for (std::size_t k = 1; k <= banded; ++k) {
        coarser_rows(fine, sizes[k - 1].height, sizes[k], rows_of(k).first, rows_of(k).second, coarse);
        put_rows(coarse, image.linear, words + starts[k]);
        std::swap(fine, coarse);
      }
      std::copy(fine.texels.begin(), fine.texels.end(), level.texels.begin() + fine.first * fine.width);
    }
  });
  for (std::size_t k = banded + 1; k < sizes.size(); ++k) {
    Rows next = make_rows(sizes[k].width, 0, sizes[k].height);
    parallel_for(sizes[k].height, kRowsPerTask, [&](std::size_t y) {
      Rows row;
      coarser_rows(level, sizes[k - 1].height, sizes[k], y, y + 1, row);
      std::copy(row.texels.begin(), row.texels.end(), next.texels.begin() + y * next.width);
    });
    level = std::move(next);
    put_rows(level, image.linear, words + starts[k]);
  }
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
  // Every level's place first, so that the table is allocated once at its final size: growing it
  // level by level would copy it and hold it twice.
  std::vector<std::vector<Size>> sizes(scene.texture_images.size());
  std::vector<std::vector<std::size_t>> starts(scene.texture_images.size());
  std::size_t total = table.texels.size();
  for (std::size_t i = 0; i < scene.texture_images.size(); ++i) {
    if (!used[i]) continue;
    const TextureImage& image = scene.texture_images[i];
    sizes[i] = level_sizes(image);
    placed[i].first_word = static_cast<dev::u32>(total);
    placed[i].levels = static_cast<dev::u32>(sizes[i].size());
    for (const Size& size : sizes[i]) {
      starts[i].push_back(total);
      total += (image.linear ? 3 : 1) * size.width * size.height;
    }
    if (total > UINT32_MAX) throw std::runtime_error("the scene's textures take more than 2^32 texel words");
  }
  table.texels.resize(total);
  for (std::size_t i = 0; i < scene.texture_images.size(); ++i)
    if (used[i]) make_levels(scene.texture_images[i], sizes[i], starts[i], table.texels.data());
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
