#include "image/image_checks.hpp"

#include <cstddef>

#include "image/image_limits.hpp"
#include "image/placement.hpp"

namespace clrt::image_detail {
namespace {

void check_size(int width, int height, const std::string& context) {
  if (width < 1 || height < 1)
    throw ImageError(context + ": the image is " + std::to_string(width) + "x" +
                     std::to_string(height) + "; it needs at least one pixel");
}

void check_length(std::size_t actual, std::size_t expected, const std::string& what,
                  const std::string& context) {
  if (actual != expected)
    throw ImageError(context + ": " + what + " holds " + std::to_string(actual) +
                     " values, the image size needs " + std::to_string(expected));
}

std::size_t pixel_count(int width, int height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

void check_image(const FloatImage& image, const std::string& context) {
  check_size(image.width, image.height, context);
  if (image.placement) check_placement(*image.placement, image.width, image.height, context);
  check_length(image.rgb.size(), 3 * pixel_count(image.width, image.height), "the RGB array",
               context);
}

void check_image(const Rgba8Image& image, const std::string& context) {
  check_size(image.width, image.height, context);
  if (image.placement) check_placement(*image.placement, image.width, image.height, context);
  if (image.frames.empty()) throw ImageError(context + ": the image has no frames");
  for (std::size_t frame = 0; frame < image.frames.size(); ++frame)
    check_length(image.frames[frame].size(), 4 * pixel_count(image.width, image.height),
                 "frame " + std::to_string(frame), context);
}

void check_declared_size(std::int64_t width, std::int64_t height, const std::string& path,
                         const std::string& format) {
  if (within_image_limits(width, height)) return;
  throw ImageError(path + ": the " + format + "'s " + std::to_string(width) + "x" +
                   std::to_string(height) + " pixels are more than clrt reads (at most " +
                   std::to_string(kMostSide) + " a side and " + std::to_string(kMostPixels) +
                   " in all)");
}

}  // namespace clrt::image_detail
