#include "image/placement.hpp"

#include <cstdint>

#include "math/number_fields.hpp"

namespace clrt::image_detail {
namespace {

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

std::string placement_text(const Placement& placement, int width, int height) {
  return std::to_string(placement.x) + "," + std::to_string(placement.y) + " " +
         size_text(width, height) + " of " +
         size_text(placement.full_width, placement.full_height);
}

Placement parse_placement_text(const std::string& text, int width, int height,
                               const std::string& context) {
  // No leading zeros, so one placement has one spelling; up to 10 digits, so every number fits
  // in 64 bits before the range checks.
  const auto numbers = read_number_fields(text, {"#,# #x# of #x#", 10, true});
  if (!numbers)
    throw ImageError(context + ": the placement \"" + text +
                     "\" is not of the form X,Y WxH of FULL_WxFULL_H");
  const auto number = [&](std::size_t i) { return static_cast<long long>((*numbers)[i - 1]); };
  if (number(3) != width || number(4) != height)
    throw ImageError(context + ": the placement \"" + text + "\" is for a " +
                     std::to_string(number(3)) + "x" + std::to_string(number(4)) +
                     " image, but the image is " + size_text(width, height));
  const long long limit = INT32_MAX;
  for (std::size_t i : {1, 2, 5, 6})
    if (number(i) > limit)
      throw ImageError(context + ": the placement \"" + text + "\" has a number above " +
                       std::to_string(limit));
  const Placement placement{static_cast<int>(number(1)), static_cast<int>(number(2)),
                            static_cast<int>(number(5)), static_cast<int>(number(6))};
  check_placement(placement, width, height, context);
  return placement;
}

void check_placement(const Placement& placement, int width, int height,
                     const std::string& context) {
  const auto fits = [](std::int64_t start, std::int64_t size, std::int64_t full) {
    return start >= 0 && start + size <= full;
  };
  if (!fits(placement.x, width, placement.full_width) ||
      !fits(placement.y, height, placement.full_height))
    throw ImageError(context + ": a " + size_text(width, height) + " image placed at " +
                     std::to_string(placement.x) + "," + std::to_string(placement.y) +
                     " does not fit in its " +
                     size_text(placement.full_width, placement.full_height) + " frame");
}

std::optional<Placement> recorded_placement(const std::optional<Placement>& placement, int width,
                                            int height) {
  if (placement && *placement == Placement{0, 0, width, height}) return std::nullopt;
  return placement;
}

}  // namespace clrt::image_detail
