#include "cl_fixture.hpp"

#include <map>
#include <memory>

#include "device/device_select.hpp"
#include "device/kernel_source.hpp"
#include "device/launch.hpp"

namespace clrt::test {

DeviceContext& device() {
  static DeviceContext context(select_devices("cpu").front());
  return context;
}

compute::program& test_program(const std::string& text) {
  static std::map<std::string, compute::program> cache;
  auto it = cache.find(text);
  if (it == cache.end())
    it = cache.emplace(text, device().build(assemble_kernel_source(text, "test.cl"))).first;
  return it->second;
}

compute::program& renderer_program() {
  static compute::program program = device().build(renderer_program_source());
  return program;
}

void run(compute::kernel& kernel, std::size_t count) {
  launch(device().queue(), kernel, count);
  device().queue().finish();
}

}  // namespace clrt::test
