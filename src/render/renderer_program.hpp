// The renderer's program for one device: every kernels/*.cl stage with the fixed options of the
// device's class (src/device/device_tuning.cpp), so every scene shares one cached build.
#pragma once

#include "device/device_context.hpp"

namespace clrt {

// `compiling` as DeviceContext::build() calls it: before a build from source.
compute::program build_renderer_program(const DeviceContext& device,
                                        const CompileNotice& compiling = {});

}  // namespace clrt
