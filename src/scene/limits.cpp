#include "scene/limits.hpp"

#include <cstdio>
#include <stdexcept>

#include "scene/scene.hpp"

namespace clrt {

std::int64_t shadow_samples(const LightSpec& light) {
  switch (light.kind) {
    case LightKind::Ambient:
      return 0;
    case LightKind::Point:
    case LightKind::Directional:
    case LightKind::Spot:
      return 1;
    case LightKind::Area:
      return light.samples;
  }
  throw std::logic_error("a light kind without shadow samples");
}

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  std::string out = text;
  const std::size_t plus = out.find("e+");
  if (plus != std::string::npos) out.erase(plus + 1, 1);
  return out;
}

std::string excerpt(std::string_view text) {
  if (text.size() <= limits::kExcerptBytes) return std::string(text);
  return std::string(text.substr(0, limits::kExcerptBytes)) + "... (" +
         std::to_string(text.size()) + " bytes)";
}

}  // namespace clrt
