// The renderer's program for one device and one transport model: every kernels/*.cl file, with
// the options of the device's profile (device/device_profile.hpp), of every integrator for its
// class (integrator_table()) and of the mode's transport model (kernels/render/transport_step.h),
// so every scene and integrator of that mode shares one cached build.
#pragma once

#include "device/device_context.hpp"
#include "render/render_options.hpp"

namespace clrt {

// Whether any of the scene's objects moves. A still scene's program is built without the motion
// code (-DCLRT_STILL_SCENE, kernels/shared/scene.h), which would cost it 4-6% of its render.
enum class SceneMotion { Still, Moving };

// `compiling` as DeviceContext::build() calls it: before a build from source.
compute::program build_renderer_program(const DeviceContext& device, RenderMode mode,
                                        SceneMotion motion, const CompileNotice& compiling = {});

}  // namespace clrt
