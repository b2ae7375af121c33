#include "render/renderer_program.hpp"

#include "device/kernel_source.hpp"
#include "render/integrator.hpp"

namespace clrt {

compute::program build_renderer_program(const DeviceContext& device,
                                        const CompileNotice& compiling) {
  return device.build(renderer_program_source(),
                      integrator_program_options(classify(device.device())), compiling);
}

}  // namespace clrt
