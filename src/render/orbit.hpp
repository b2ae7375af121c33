// The camera of an animation's frames: a turntable that orbits the eye about the axis through
// `lookat` along `up`, frame 0 being the scene's own camera.
#pragma once

#include <cstdint>

#include "scene/scene.hpp"

namespace clrt {

// Frame `frame` (from 0) of `frames` frames that sweep `orbit_degrees` in all: the eye turned
// by orbit_degrees * frame / frames, counter-clockwise seen from above (along -up). A 360
// degree orbit so closes on itself without repeating frame 0. lookat, up and fov stay.
CameraSpec orbit_camera(const CameraSpec& camera, double orbit_degrees, std::uint32_t frame,
                        std::uint32_t frames);

}  // namespace clrt
