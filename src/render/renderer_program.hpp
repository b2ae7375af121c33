// The renderer's program for one device and one transport model: every kernels/*.cl file, with
// the options of the device's profile (device/device_profile.hpp), of every integrator for its
// class (integrator_table()) and of the mode's transport model (kernels/render/transport_step.h),
// so every scene and integrator of that mode shares one cached build.
#pragma once

#include "device/device_context.hpp"
#include "render/render_options.hpp"

namespace clrt {

// `compiling` as DeviceContext::build() calls it: before a build from source.
compute::program build_renderer_program(const DeviceContext& device, RenderMode mode,
                                        const CompileNotice& compiling = {});

}  // namespace clrt
