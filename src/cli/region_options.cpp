#include "cli/region_options.hpp"

#include <cmath>
#include <sstream>

#include "render/usage_error.hpp"

namespace clrt {
namespace {

std::string numbers_text(const std::array<double, 4>& v) {
  std::ostringstream out;
  out << v[0] << "," << v[1] << "," << v[2] << "," << v[3];
  return out.str();
}

}  // namespace

std::string parse_region_numbers(const std::string& text, bool whole,
                                 std::optional<std::array<double, 4>>& out) {
  std::array<double, 4> v{};
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  for (int k = 0; k < 4; ++k) {
    if (k > 0 && in.get() != ',') return "takes four numbers x0,x1,y0,y1";
    if (!(in >> v[k]) || !std::isfinite(v[k])) return "takes four numbers x0,x1,y0,y1";
    if (whole && (v[k] != std::floor(v[k]) || v[k] < 0 || v[k] > 4294967295.0))
      return "takes whole pixel numbers from 0, found " + text;
  }
  if (in.peek() != std::char_traits<char>::eof()) return "takes four numbers x0,x1,y0,y1";
  out = v;
  return {};
}

std::optional<PixelRect> resolve_region(const RegionRequest& request, int width, int height) {
  if (request.pixel_bounds && request.crop_window)
    throw UsageError("--pixel-bounds and --crop-window name the region twice: give one");
  std::array<double, 4> b{};
  std::string given;
  if (request.pixel_bounds) {
    b = *request.pixel_bounds;
    given = "--pixel-bounds " + numbers_text(b);
  } else if (request.crop_window) {
    const std::array<double, 4>& c = *request.crop_window;
    given = "--crop-window " + numbers_text(c);
    for (double f : c)
      if (f < 0 || f > 1) throw UsageError(given + ": fractions of the image lie in [0, 1]");
    b = {std::ceil(width * c[0]), std::ceil(width * c[1]), std::ceil(height * c[2]),
         std::ceil(height * c[3])};
  } else {
    return std::nullopt;
  }
  if (b[1] <= b[0] || b[3] <= b[2])
    throw UsageError(given + ": the region is empty or inverted (x0 < x1 and y0 < y1 are needed)");
  if (b[1] > width || b[3] > height)
    throw UsageError(given + ": the region reaches outside the " + std::to_string(width) + "x" +
                     std::to_string(height) + " image");
  return PixelRect{static_cast<std::uint32_t>(b[0]), static_cast<std::uint32_t>(b[2]),
                   static_cast<std::uint32_t>(b[1] - b[0]), static_cast<std::uint32_t>(b[3] - b[2])};
}

}  // namespace clrt
