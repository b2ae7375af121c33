#include "render/integrator.hpp"

#include <algorithm>
#include <cctype>

#include "render/megakernel.hpp"
#include "render/usage_error.hpp"
#include "render/wavefront.hpp"

namespace clrt {

const char* integrator_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Wavefront: return "wavefront";
    case IntegratorKind::Megakernel: return "megakernel";
  }
  return "unknown";
}

std::optional<IntegratorKind> parse_integrator(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (IntegratorKind kind : {IntegratorKind::Wavefront, IntegratorKind::Megakernel})
    if (lower == integrator_name(kind)) return kind;
  return std::nullopt;
}

void check_megakernel_depth(std::uint32_t max_depth, std::uint32_t stack_depth) {
  if (max_depth > stack_depth)
    throw UsageError("the megakernel's ray stack holds trees of depth " +
                     std::to_string(stack_depth) + " on this device, the maximum depth is " +
                     std::to_string(max_depth) +
                     ": lower --max-depth or use --integrator wavefront");
}

std::unique_ptr<Integrator> make_integrator(IntegratorKind kind, DeviceContext& device,
                                            const compute::program& program,
                                            const DeviceFrame& frame,
                                            const IntegratorConfig& config) {
  switch (kind) {
    case IntegratorKind::Wavefront:
      return std::make_unique<WavefrontIntegrator>(device, program, frame, config);
    case IntegratorKind::Megakernel:
      return std::make_unique<MegakernelIntegrator>(device, program, frame, config);
  }
  return nullptr;
}

}  // namespace clrt
