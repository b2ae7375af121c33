// The Markdown tables clrt-embree-compare prints.
#pragma once

#include <vector>

#include "compare_scene.hpp"

namespace clrt::compare {

// One row per ray set (a skipped scene gets one row saying why), then the build times.
void print_report(const std::vector<SceneResult>& scenes);

}  // namespace clrt::compare
