#include "scene/texture_rules.hpp"

namespace clrt {

std::optional<std::string> texture_scale_problem(double value) {
  if (value == 0) return "a texture's scale must not be 0";
  return std::nullopt;
}

}  // namespace clrt
