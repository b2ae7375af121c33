// A host table that a CPU device reads in place (CL_MEM_USE_HOST_PTR) may be freed only once the
// runtime has deleted every buffer over it, which OpenCL allows to happen after the last
// clReleaseMemObject returns. Freeing it earlier let Intel's CPU runtime, under load, return a
// later render's image as garbage (test_repeated_renders under test_render@intel).
#include <catch2/catch.hpp>

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "cl_fixture.hpp"
#include "math/page_aligned_allocator.hpp"

using namespace clrt;

namespace {

using Table = std::vector<float, PageAlignedAllocator<float>>;

// Whether `watch` expires within a generous bound once nothing queued uses the buffer; a runtime
// may delete buffers on a thread of its own.
bool expires(const std::weak_ptr<const void>& watch) {
  for (int i = 0; i < 1000 && !watch.expired(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return watch.expired();
}

}  // namespace

TEST_CASE("a shared host table lives as long as the device's buffer over it, then is freed",
          "[device][shared-memory]") {
  DeviceContext& device = test::device();
  auto table = std::make_shared<Table>(4096);
  for (std::size_t i = 0; i < table->size(); ++i) (*table)[i] = static_cast<float>(i) * 0.5f;
  const std::weak_ptr<const void> watch = table;
  const std::size_t bytes = sizeof(float) * table->size();
  {
    Global<const float> shared(device.share_host_memory(table->data(), bytes, "test table", table));
    table.reset();
    REQUIRE_FALSE(watch.expired());
    // The device reads the table through the buffer after the caller has let go of it.
    const std::vector<float> back = download(device, shared, 4096);
    for (std::size_t i = 0; i < back.size(); ++i) REQUIRE(back[i] == static_cast<float>(i) * 0.5f);
    CHECK_FALSE(watch.expired());
  }
  device.queue().finish();
  CHECK(expires(watch));
}

TEST_CASE("a table shared by several buffers is freed after the last of them",
          "[device][shared-memory]") {
  DeviceContext& device = test::device();
  auto table = std::make_shared<Table>(1024, 2.0f);
  const std::weak_ptr<const void> watch = table;
  const std::size_t bytes = sizeof(float) * table->size();
  auto first = std::make_unique<compute::buffer>(
      device.share_host_memory(table->data(), bytes, "first view", table));
  {
    const compute::buffer second = device.share_host_memory(table->data(), bytes, "second view", table);
    table.reset();
  }
  device.queue().finish();
  // The second buffer is gone; the first still reads the table.
  const std::vector<float> back = download(device, Global<const float>(*first), 1024);
  CHECK(back.front() == 2.0f);
  CHECK(back.back() == 2.0f);
  CHECK_FALSE(watch.expired());
  first.reset();
  device.queue().finish();
  CHECK(expires(watch));
}
