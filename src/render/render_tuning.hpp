// What a render launches with on one device: the device's profile (device/device_profile.hpp)
// with the command line's overrides. The checks before a render and the renderer both ask here.
#pragma once

#include "device/device_profile.hpp"
#include "render/render_options.hpp"

namespace clrt {

DeviceProfile render_tuning(const compute::device& device, const RenderOptions& options);

}  // namespace clrt
