// Short labels for the table: how much geometry a scene holds.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace clrt::compare {

// 1234 -> "1234", 36610 -> "36.6k", 1000000 -> "1M".
std::string short_count(double n);

// e.g. "7381 spheres, 2 tris" or "1M tris x 100 inst (100M)".
std::string primitive_label(const Scene& scene);

}  // namespace clrt::compare
