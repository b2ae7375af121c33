#include "cl_fixture.hpp"

#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>

#include "device/device_select.hpp"
#include "device/device_profile.hpp"
#include "device/kernel_source.hpp"
#include "render/renderer_program.hpp"

namespace clrt::test {

// The context and the programs live until the process ends and are never destroyed: releasing
// them from static destructors, after the driver's own statics are gone, corrupts Oclgrind's
// heap at exit.
DeviceContext& device() {
  static DeviceContext& context = *new DeviceContext(select_devices(test_device_spec()).front());
  return context;
}

std::size_t local_size() { return device_profile(device().device()).local_size; }

std::string test_device_spec() {
  const char* spec = std::getenv("CLRT_TEST_DEVICE");
  return spec && *spec ? spec : "cpu";
}

compute::program& test_program(const std::string& text) {
  static std::map<std::string, compute::program>& cache = *new std::map<std::string, compute::program>;
  auto it = cache.find(text);
  if (it == cache.end())
    it = cache.emplace(text, device().build(assemble_kernel_source(text, "test.cl"))).first;
  return it->second;
}

compute::program& renderer_program(RenderMode mode) {
  static std::map<RenderMode, compute::program>& programs = *new std::map<RenderMode, compute::program>;
  auto it = programs.find(mode);
  if (it == programs.end()) it = programs.emplace(mode, build_renderer_program(device(), mode, SceneFeatures{true, true})).first;
  return it->second;
}

void check_binding(const compute::kernel& kernel, const std::vector<ExpectedArg>& expected) {
  std::string problems;
  for (const std::string& line : signature_mismatches(kernel, expected)) problems += line + "\n";
  if (!problems.empty()) throw std::logic_error("kernel binding mismatch:\n" + problems);
}

}  // namespace clrt::test
