#include "render/device_preparation.hpp"

#include "render/renderer_program.hpp"

namespace clrt {

std::vector<PreparedDevice> prepare_devices(const std::vector<DeviceEntry>& devices,
                                            RenderMode mode, const CompileNotice& compiling) {
  std::vector<PreparedDevice> prepared;
  for (const DeviceEntry& entry : devices) {
    PreparedDevice d;
    d.context = std::make_unique<DeviceContext>(entry);
    d.program = build_renderer_program(*d.context, mode, d.features, compiling);
    d.mode = mode;
    prepared.push_back(std::move(d));
  }
  return prepared;
}

}  // namespace clrt
