// The rules a texture's options follow, one set for a `.ray` `texture` and an MTL map alike, so
// that what one refuses the other refuses too (docs/scene-format.md#textures).
#pragma once

#include <optional>
#include <string>

namespace clrt {

// Why `value` cannot be a component of a texture's scale (`texture ... scale`, an MTL map's
// `-s`), or nothing when it can. A scale of 0 would show one texel over the whole surface.
std::optional<std::string> texture_scale_problem(double value);

}  // namespace clrt
