#include "image/display_transform.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "image/eight_bit_rows.hpp"

namespace clrt {

double srgb_encode(double linear) {
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

double filmic_curve(double x) {
  // From x = 7.25 up the curve is above 1 and clamped; capping x keeps an infinity, or a value
  // whose square overflows, from turning the ratio into inf / inf.
  x = std::min(x, 64.0);
  const double curved = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
  return std::clamp(curved, 0.0, 1.0);
}

double display_value(double linear, const DisplayTransform& display) {
  const double exposed = linear * std::exp2(display.exposure);
  // Zero, negatives and NaN are black; the power below is undefined for them.
  if (!(exposed > 0)) return 0;
  const double toned =
      display.curve == ToneCurve::Filmic ? filmic_curve(exposed) : std::min(exposed, 1.0);
  if (display.srgb) return srgb_encode(toned);
  return display.gamma == 1 ? toned : std::pow(toned, 1 / display.gamma);
}

std::uint8_t display_byte(float linear, const DisplayTransform& display) {
  if (display.identity()) return image_detail::quantize_channel(linear);
  // Rounded to float before quantising, as clrt-view has always shown its gamma.
  return image_detail::quantize_channel(static_cast<float>(display_value(linear, display)));
}

namespace {

const std::pair<const char*, ToneCurve> kCurveNames[] = {{"clamp", ToneCurve::Clamp},
                                                         {"filmic", ToneCurve::Filmic}};

}  // namespace

std::vector<std::string> tone_curve_names() {
  std::vector<std::string> names;
  for (const auto& [name, curve] : kCurveNames) names.push_back(name);
  return names;
}

std::string tone_curve_name(ToneCurve curve) {
  for (const auto& [name, known] : kCurveNames)
    if (curve == known) return name;
  return "clamp";
}

std::optional<ToneCurve> tone_curve_from_name(const std::string& name) {
  for (const auto& [known, curve] : kCurveNames)
    if (name == known) return curve;
  return std::nullopt;
}

}  // namespace clrt
