// Every kernel's argument structure (each integrator's, through its row of integrator_table();
// src/render/stage_args.hpp, src/geometry/bvh_query_args.hpp) against the kernel's own signature as the device reports it: names, types, address space and
// constness, in order. And the check itself: a kernel whose signature disagrees with its
// structure is reported, naming the argument.
#include <catch2/catch.hpp>

#include <string>
#include <tuple>
#include <vector>

#include "cl_fixture.hpp"
#include "geometry/bvh_query_args.hpp"
#include "render/integrator.hpp"
#include "render/stage_args.hpp"

using namespace clrt;

namespace {

// The kernels every integrator shares (the resolver's, the compactor's, the profiler's); each
// integrator's own are checked through its row.
using SharedKernels =
    std::tuple<ResolveArgs, CompactCountArgs, CompactScanArgs, CompactScatterArgs,
               CountRayKindsArgs, FoldRayCountsArgs, AddRayKindsArgs, AddShadowRaysArgs,
               CommitRayCountsArgs>;

template <class Args>
std::vector<std::string> mismatches(const compute::program& program) {
  const TypedKernel<Args> kernel(program);
  return signature_mismatches(kernel.kernel(), expected_args(Args{}));
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

// A program whose `shadow` kernel takes the renderer's arguments with two of them swapped.
const char* const kSwappedShadow = R"CL(
#include "render/shadow_test.h"
__kernel void shadow(SCENE_PARAMS, __global const RenderParams* params,
                     __global const uint* count, __global const ShadowRay* shadows,
                     __global float4* visible) {}
)CL";

// A `resolve` whose sample count is a pointer and that lacks its output.
const char* const kWrongResolve = R"CL(
__kernel void resolve(__global const float4* sample_colour, __global const uint* samples,
                      uint pixel_count) {}
)CL";

// A `generate` that writes through a const pointer and gives an argument another name.
const char* const kRenamedGenerate = R"CL(
#include "render/common.h"
__kernel void generate(__global const Camera* camera, uint region_x, uint region_y,
                       uint region_width, uint first, uint first_sample,
                       uint pixel_samples, uint sample_count, __global const Ray* rays) {}
)CL";

}  // namespace

TEST_CASE("every integrator's kernels match the argument structures it binds", "[bindings]") {
  const compute::program& program = test::renderer_program();
  for (const IntegratorEntry& entry : integrator_table()) {
    INFO(entry.name);
    CHECK(joined(entry.binding_mismatches(program)).empty());
  }
}

TEST_CASE("the shared kernels' argument structures match their signatures", "[bindings]") {
  const compute::program& program = test::renderer_program();
  std::apply(
      [&](auto... args) {
        (
            [&] {
              using Args = decltype(args);
              INFO(Args::kName);
              CHECK(joined(mismatches<Args>(program)).empty());
            }(),
            ...);
      },
      SharedKernels{});
}

TEST_CASE("the BVH query kernels' argument structures match their signatures", "[bindings]") {
  const compute::program& program =
      test::test_program("#include \"geometry/bvh_query_kernels.h\"\n");
  CHECK(joined(mismatches<BvhClosestHitsArgs>(program)).empty());
  CHECK(joined(mismatches<BvhAnyHitsArgs>(program)).empty());
}

TEST_CASE("swapped kernel arguments are reported by name", "[bindings]") {
  const std::string report = joined(mismatches<ShadowArgs>(test::test_program(kSwappedShadow)));
  INFO(report);
  CHECK(report.find("shadow argument 10 is 'count', the host binds 'shadows'") != std::string::npos);
  CHECK(report.find("shadow argument 11 is 'shadows', the host binds 'count'") != std::string::npos);
  CHECK(report.find("has type uint*, the host binds ShadowRay*") != std::string::npos);
}

TEST_CASE("wrong types, constness and counts are reported", "[bindings]") {
  const std::string report = joined(mismatches<ResolveArgs>(test::test_program(kWrongResolve)));
  INFO(report);
  CHECK(report.find("the kernel takes 3 arguments, the host structure has 6") != std::string::npos);
  CHECK(report.find("'samples' has type uint*, the host binds uint") != std::string::npos);
  CHECK(report.find("'samples': the host binds a value") != std::string::npos);

  const std::string renamed =
      joined(mismatches<GenerateArgs>(test::test_program(kRenamedGenerate)));
  INFO(renamed);
  CHECK(renamed.find("is 'first', the host binds 'first_pixel'") != std::string::npos);
  CHECK(renamed.find("'rays': the host writes to it, the kernel has it const") != std::string::npos);
}

TEST_CASE("launching through a mismatched structure fails before the launch", "[bindings]") {
  ShadowArgs args;
  CHECK_THROWS_WITH(test::run(test::test_program(kSwappedShadow), args, 1),
                    Catch::Contains("kernel binding mismatch"));
}
