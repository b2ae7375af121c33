// The renderer's program for one device and one transport model: every kernels/*.cl stage with
// the fixed options of the device's class (src/device/device_tuning.cpp) and the mode's model
// (kernels/render/transport_step.h), so every scene rendered in that mode shares one cached
// build.
#pragma once

#include "device/device_context.hpp"
#include "render/render_options.hpp"

namespace clrt {

// `compiling` as DeviceContext::build() calls it: before a build from source.
compute::program build_renderer_program(const DeviceContext& device, RenderMode mode,
                                        const CompileNotice& compiling = {});

}  // namespace clrt
