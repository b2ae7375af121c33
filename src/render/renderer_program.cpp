#include "render/renderer_program.hpp"

#include <string>

#include "device/kernel_source.hpp"
#include "render/integrator.hpp"
#include "shared/scene.h"

namespace clrt {
namespace {

dev::u32 transport_model(RenderMode mode) {
  switch (mode) {
    case RenderMode::Trace: return CLRT_MODE_TRACE;
    case RenderMode::Cast: return CLRT_MODE_CAST;
    case RenderMode::Path: return CLRT_MODE_PATH;
  }
  return CLRT_MODE_TRACE;
}

}  // namespace

compute::program build_renderer_program(const DeviceContext& device, RenderMode mode,
                                        const CompileNotice& compiling) {
  const std::string options = integrator_program_options(classify(device.device())) +
                              " -DCLRT_TRANSPORT=" + std::to_string(transport_model(mode));
  return device.build(renderer_program_source(), options, compiling);
}

}  // namespace clrt
