// The renderer's program for one device and one transport model: every kernels/*.cl file, with
// the options of the device's profile (device/device_profile.hpp), of every integrator for its
// class (integrator_table()) and of the mode's transport model (kernels/render/transport_step.h),
// so every scene and integrator of that mode shares one cached build.
#pragma once

#include "device/device_context.hpp"
#include "render/render_options.hpp"

namespace clrt {

// What the scene needs of the program beyond its mode. A still scene's program is built without
// the motion code (-DCLRT_STILL_SCENE, kernels/shared/scene.h), which would cost it 4-6% of its
// render, and a scene without textures without the texture code (-DCLRT_UNTEXTURED,
// kernels/shared/texture.h): no texture coordinates at hits, no ray cones.
struct SceneFeatures {
  bool moving = false;    // an object moves (the scene has a motion table)
  bool textured = false;  // a material has a texture

  bool operator==(const SceneFeatures& other) const {
    return moving == other.moving && textured == other.textured;
  }
};

// `compiling` as DeviceContext::build() calls it: before a build from source.
compute::program build_renderer_program(const DeviceContext& device, RenderMode mode,
                                        SceneFeatures features, const CompileNotice& compiling = {});

}  // namespace clrt
