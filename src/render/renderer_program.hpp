// The renderer's program for one device: every kernels/*.cl stage with the fixed options of the
// device's class (src/device/device_tuning.cpp), so every scene shares one cached build.
#pragma once

#include <functional>

#include "device/device_context.hpp"

namespace clrt {

// `compiling` as DeviceContext::build() calls it: when the program cache does not hold it.
compute::program build_renderer_program(const DeviceContext& device,
                                        const std::function<void()>& compiling = {});

}  // namespace clrt
