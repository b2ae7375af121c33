#include "render/renderer_program.hpp"

#include <string>

#include "device/kernel_source.hpp"
#include "render/frame_setup.hpp"
#include "render/integrator.hpp"

namespace clrt {

compute::program build_renderer_program(const DeviceContext& device, RenderMode mode,
                                        SceneFeatures features, const CompileNotice& compiling) {
  const std::string options = integrator_program_options(classify(device.device())) +
                              " -DCLRT_TRANSPORT=" + std::to_string(device_mode(mode)) +
                              (features.moving ? "" : " -DCLRT_STILL_SCENE") +
                              (features.textured ? "" : " -DCLRT_UNTEXTURED");
  return device.build(renderer_program_source(), options, compiling);
}

}  // namespace clrt
