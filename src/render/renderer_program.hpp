// The renderer's program for one device: every kernels/*.cl file, with the options of the
// device's profile (device/device_profile.hpp) and of every integrator for its class
// (integrator_table()), so every scene and integrator shares one cached build.
#pragma once

#include "device/device_context.hpp"

namespace clrt {

// `compiling` as DeviceContext::build() calls it: before a build from source.
compute::program build_renderer_program(const DeviceContext& device,
                                        const CompileNotice& compiling = {});

}  // namespace clrt
