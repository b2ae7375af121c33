#include "render/render_tuning.hpp"

namespace clrt {

DeviceProfile render_tuning(const compute::device& device, const RenderOptions& options) {
  DeviceProfile t = device_profile(device);
  if (options.local_size) t.local_size = options.local_size;
  if (options.wavefront) t.wavefront = options.wavefront;
  if (options.lanes) t.lanes = options.lanes;
  return t;
}

}  // namespace clrt
