#include "render/renderer_program.hpp"

#include "device/device_tuning.hpp"
#include "device/kernel_source.hpp"

namespace clrt {

compute::program build_renderer_program(const DeviceContext& device,
                                        const CompileNotice& compiling) {
  return device.build(renderer_program_source(), tuning_for(device.device()).program_options(),
                      compiling);
}

}  // namespace clrt
