// The driver fault behind clrt's rule for device functions (kernels/shared/common.h): a float3
// passed to a function that the compiler keeps out of line. Intel's CPU runtime, vectorising a
// work-group 16 wide, packs the lanes' float3 arguments 12 bytes apart and reads them 16 apart,
// so most work-items compute with other work-items' values. The test says whether the device
// under test has the fault and requires that the rule's two forms (forced inline, float4 across
// the call) give every work-item its own answer there.
#include <catch2/catch.hpp>

#include <iostream>

#include "cl_fixture.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const char* const kKernels = R"CL(
#include "shared/common.h"

__attribute__((noinline)) float3 blend_out_of_line(float3 a, float3 b) { return a * 2.0f + b; }
CLRT_INLINE float3 blend_inline(float3 a, float3 b) { return a * 2.0f + b; }
CLRT_CALLABLE float4 blend_callable(float4 a, float4 b) { return a * 2.0f + b; }

__kernel void float3_calls(__global const float4* a, __global const float4* b, uint count,
                           __global float4* out_of_line, __global float4* inlined,
                           __global float4* callable) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  out_of_line[i] = (float4)(blend_out_of_line(a[i].xyz, b[i].xyz), 0.0f);
  inlined[i] = (float4)(blend_inline(a[i].xyz, b[i].xyz), 0.0f);
  callable[i] = (float4)(blend_callable((float4)(a[i].xyz, 0.0f), (float4)(b[i].xyz, 0.0f)).xyz, 0.0f);
}
)CL";

struct Float3CallsArgs {
  static constexpr const char* kName = "float3_calls";
  Global<const dev::f4> a, b;
  cl_uint count = 0;
  Global<dev::f4> out_of_line, inlined, callable;
  CLRT_KERNEL_ARGS(a, b, count, out_of_line, inlined, callable)
};

// Work-items whose result is not 2a + b for their own a and b.
int wrong_items(const std::vector<dev::f4>& a, const std::vector<dev::f4>& b,
                const std::vector<dev::f4>& out) {
  int wrong = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const bool right = out[i].x == a[i].x * 2.0f + b[i].x && out[i].y == a[i].y * 2.0f + b[i].y &&
                       out[i].z == a[i].z * 2.0f + b[i].z;
    if (!right) ++wrong;
  }
  return wrong;
}

}  // namespace

TEST_CASE("float3 values reach every work-item's function call intact under clrt's rule",
          "[device][driver-faults]") {
  constexpr std::size_t kCount = 256;  // four work-groups of 64, vectorised on Intel's runtime
  std::vector<dev::f4> a(kCount), b(kCount);
  for (std::size_t i = 0; i < kCount; ++i) {
    const auto f = static_cast<float>(i);
    a[i] = {f, 1000.0f + f, -f, 0.0f};
    b[i] = {0.5f * f, 3.0f, 7.0f - f, 0.0f};
  }
  const Global<dev::f4> out_of_line = allocate<dev::f4>(kCount), inlined = allocate<dev::f4>(kCount),
                        callable = allocate<dev::f4>(kCount);
  run(test_program(kKernels),
      Float3CallsArgs{upload(a), upload(b), static_cast<cl_uint>(kCount), out_of_line, inlined,
                      callable},
      kCount, 64);
  const int faulty = wrong_items(a, b, download(out_of_line, kCount));
  // Reported whatever the outcome: docs/devices.md lists the implementations that have it.
  std::cout << "float3 arguments of an out-of-line function on " << device().name() << ": "
            << (faulty == 0 ? "intact" : "garbled in " + std::to_string(faulty) + " of " +
                                             std::to_string(kCount) + " work-items (driver fault)")
            << "\n";
  CHECK(wrong_items(a, b, download(inlined, kCount)) == 0);
  CHECK(wrong_items(a, b, download(callable, kCount)) == 0);
}
