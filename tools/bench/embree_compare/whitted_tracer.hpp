// A Whitted ray tracer for the same .ray scenes on Embree 3's single-ray API, written
// independently of clrt's kernels from the contract (docs/ray-format.md), so that clrt's whole
// command can be timed against a CPU tracer's (clrt-embree-render): one ray through each pixel
// centre, the contract's local terms, shadow rays, reflection and refraction up to the scene's
// depth, shaded on the host in double precision.
#pragma once

#include <string>

#include "embree_scene.hpp"
#include "image/image.hpp"
#include "render/render_options.hpp"
#include "scene/scene.hpp"

namespace clrt::compare {

// The lights of kinds this tracer does not trace (it knows ambient, point, directional and spot
// lights), e.g. "1 area light", and "glowing surfaces" and "an environment image", which it does
// not show either; empty when it can render the scene's lights.
std::string unsupported_lights(const Scene& scene);

// The scene at the options' size and depth (one sample per pixel, trace mode) on `threads`
// threads; `embree` holds the scene's geometry.
FloatImage render_whitted(const Scene& scene, const EmbreeScene& embree, const RenderOptions& options,
                          int threads);

}  // namespace clrt::compare
