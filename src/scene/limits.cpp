#include "scene/limits.hpp"

#include <cstdio>

#include "scene/light_kinds.hpp"
#include "scene/scene.hpp"

namespace clrt {

std::int64_t shadow_samples(const LightSpec& light) {
  return light_kind(light.kind).shadow_samples(light);
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
