#include "render/renderer_program.hpp"

#include <string>

#include "device/kernel_source.hpp"
#include "render/frame_setup.hpp"
#include "render/integrator.hpp"

namespace clrt {

compute::program build_renderer_program(const DeviceContext& device, RenderMode mode,
                                        SceneMotion motion, const CompileNotice& compiling) {
  const std::string options = integrator_program_options(classify(device.device())) +
                              " -DCLRT_TRANSPORT=" + std::to_string(device_mode(mode)) +
                              (motion == SceneMotion::Still ? " -DCLRT_STILL_SCENE" : "");
  return device.build(renderer_program_source(), options, compiling);
}

}  // namespace clrt
