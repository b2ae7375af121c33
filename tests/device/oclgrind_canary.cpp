// A kernel that reads one element past its buffer, on purpose: CTest's
// oclgrind_reports_an_out_of_bounds_read runs it under Oclgrind and passes only when Oclgrind
// reports it, so a silent Oclgrind cannot pass for a clean one. Hidden from ordinary runs.
#include <catch2/catch.hpp>

#include "cl_fixture.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const char* const kCanaryKernels = R"CL(
__kernel void read_past_the_end(__global const float* in, uint count, __global float* out) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  out[i] = in[i + 1];
}
)CL";

struct ReadPastTheEndArgs {
  static constexpr const char* kName = "read_past_the_end";
  Global<const float> in;
  cl_uint count = 0;
  Global<float> out;
  CLRT_KERNEL_ARGS(in, count, out)
};

}  // namespace

TEST_CASE("a kernel reading past its buffer", "[.oclgrind-canary]") {
  const std::vector<float> in(16, 1.0f);
  const Global<float> out = allocate<float>(16);
  run(test_program(kCanaryKernels), ReadPastTheEndArgs{upload(in), 16, out}, 16);
  CHECK(download(out, 15) == std::vector<float>(15, 1.0f));
}
