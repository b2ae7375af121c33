#include "image/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "image/image_checks.hpp"

namespace clrt {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Size {
  int width = 0, height = 0;
};

Size checked_size(const AnyImage& image, const char* which) {
  return std::visit(
      [&](const auto& i) {
        image_detail::check_image(i, std::string("cannot compare image ") + which);
        if constexpr (std::is_same_v<std::decay_t<decltype(i)>, Rgba8Image>)
          if (i.frames.size() != 1)
            throw ImageError(std::string("cannot compare image ") + which + ": it has " +
                             std::to_string(i.frames.size()) + " frames; pick one");
        return Size{i.width, i.height};
      },
      image);
}

// The RGBA frame to compare: the image's own, or its quantised floats kept in `storage`.
const std::vector<std::uint8_t>& eight_bit_frame(const AnyImage& image, Rgba8Image& storage) {
  if (const auto* rgba = std::get_if<Rgba8Image>(&image)) return rgba->frames.front();
  storage = quantize(std::get<FloatImage>(image));
  return storage.frames.front();
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Two passes over `diff(i)`, the difference of sample i: the statistics, then the difference
// image scaled by the largest finite difference. Nothing but the result is stored.
template <typename Diff>
ImageDifference summarise(const Diff& diff, Size size, double peak, double threshold) {
  ImageDifference result;
  result.pixels = static_cast<std::uint64_t>(size.width) * static_cast<std::uint64_t>(size.height);
  const std::size_t samples = 3 * static_cast<std::size_t>(result.pixels);
  double largest_finite = 0, squares = 0;
  for (std::size_t i = 0; i < samples; i += 3) {
    bool differs = false;
    for (std::size_t c = i; c < i + 3; ++c) {
      const double d = diff(c);
      result.largest = std::max(result.largest, d);
      if (std::isfinite(d)) largest_finite = std::max(largest_finite, d);
      squares += d * d;
      differs |= d > threshold;
    }
    result.differing += differs;
  }
  const double mean_square = squares / static_cast<double>(samples);
  result.psnr = mean_square == 0 ? kInfinity : 10.0 * std::log10(peak * peak / mean_square);
  std::vector<float> scaled(samples);
  for (std::size_t i = 0; i < samples; ++i) {
    const double d = diff(i);
    scaled[i] = !std::isfinite(d)       ? 1.0f
                : largest_finite > 0.0 ? static_cast<float>(d / largest_finite)
                                       : 0.0f;
  }
  result.difference = FloatImage(size.width, size.height, std::move(scaled));
  return result;
}

}  // namespace

ImageDifference compare_images(const AnyImage& a, const AnyImage& b, double threshold) {
  const Size size_a = checked_size(a, "A"), size_b = checked_size(b, "B");
  if (size_a.width != size_b.width || size_a.height != size_b.height)
    throw ImageError("cannot compare a " + std::to_string(size_a.width) + "x" +
                     std::to_string(size_a.height) + " image with a " +
                     std::to_string(size_b.width) + "x" + std::to_string(size_b.height) + " one");
  const bool floats = std::holds_alternative<FloatImage>(a) && std::holds_alternative<FloatImage>(b);
  ImageDifference result;
  if (floats) {
    const std::vector<float>& fa = std::get<FloatImage>(a).rgb;
    const std::vector<float>& fb = std::get<FloatImage>(b).rgb;
    result = summarise(
        [&](std::size_t i) {
          const double d = std::fabs(double{fa[i]} - double{fb[i]});
          return same_bits(fa[i], fb[i]) ? 0.0 : std::isnan(d) ? kInfinity : d;
        },
        size_a, 1.0, threshold);
  } else {
    Rgba8Image storage_a, storage_b;
    const std::vector<std::uint8_t>& ra = eight_bit_frame(a, storage_a);
    const std::vector<std::uint8_t>& rb = eight_bit_frame(b, storage_b);
    // Sample i (R, G, B of pixel i / 3) is byte i + i / 3 of an RGBA frame.
    result = summarise(
        [&](std::size_t i) { return double(std::abs(int{ra[i + i / 3]} - int{rb[i + i / 3]})); },
        size_a, 255.0, threshold);
  }
  result.floats = floats;
  return result;
}

}  // namespace clrt
