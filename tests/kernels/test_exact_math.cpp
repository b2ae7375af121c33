// kernels/math/exact.h on the device against the host. The vector functions must give exactly
// the bits of IEEE 754 single precision evaluated in their stated order (what makes every
// OpenCL implementation render the same image); exact_log2, exact_exp2, exact_atan and power
// must be within 2 ulp of the true value, computed in double.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "cl_fixture.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const char* const kKernels = R"CL(
#include "math/exact.h"

__kernel void vector_math(__global const float4* a, __global const float4* b, uint count,
                          __global float4* out) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float3 x = a[i].xyz, y = b[i].xyz;
  out[4 * i] = (float4)(dot3(x, y), length3(x), dot4(a[i], b[i]), dot2(x.xy, y.xy));
  out[4 * i + 1] = (float4)(cross3(x, y), 0.0f);
  out[4 * i + 2] = (float4)(normalize3(x), 0.0f);
  out[4 * i + 3] = (float4)(exact_log2(a[i].w), exact_exp2(b[i].w), power(fabs(a[i].x), fabs(b[i].w)),
                          exact_atan(a[i].y / b[i].y));
}
)CL";

struct VectorMathArgs {
  static constexpr const char* kName = "vector_math";
  Global<const dev::f4> a, b;
  cl_uint count = 0;
  Global<dev::f4> out;
  CLRT_KERNEL_ARGS(a, b, count, out)
};

std::uint32_t bits(float f) {
  std::uint32_t u = 0;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// Distance in units in the last place between a float and the true value.
double ulps(float got, double truth) {
  if (std::isinf(truth)) return std::isinf(got) && (got > 0) == (truth > 0) ? 0.0 : 1e30;
  const double ulp = std::nextafter(static_cast<float>(std::fabs(truth)), INFINITY) -
                     static_cast<float>(std::fabs(truth));
  const double tiny = std::ldexp(1.0, -149);  // subnormal spacing
  return std::fabs(static_cast<double>(got) - truth) / std::max(ulp, tiny);
}

}  // namespace

TEST_CASE("exact.h's vector functions give IEEE 754's bits, in their stated order", "[kernels][exact-math]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-100.0f, 100.0f), logs(-140.0f, 127.0f);
  constexpr std::size_t kCount = 4096;
  std::vector<dev::f4> a(kCount), b(kCount);
  for (std::size_t i = 0; i < kCount; ++i) {
    // w: a positive number spread over the whole float range (log2's input), an exponent (exp2's).
    a[i] = {coordinate(rng), coordinate(rng), coordinate(rng), std::ldexp(1.0f + std::fabs(coordinate(rng)) / 100.0f,
                                                                          static_cast<int>(logs(rng)))};
    b[i] = {coordinate(rng), coordinate(rng), coordinate(rng), logs(rng)};
  }
  a[0] = {0.0f, 0.0f, 0.0f, 1.0f};               // log2(1) = 0
  a[1].w = std::numeric_limits<float>::denorm_min();
  b[2].w = 0.0f;                                 // exp2(0) = 1, x^0 = 1
  b[3].w = -149.0f;                              // the smallest subnormal
  b[4].w = 127.99f;                              // just under the largest float
  b[5].w = 128.0f;                               // overflows
  const Global<dev::f4> out = allocate<dev::f4>(4 * kCount);
  run(test_program(kKernels), VectorMathArgs{upload(a), upload(b), static_cast<cl_uint>(kCount), out},
      kCount);
  const std::vector<dev::f4> got = download(out, 4 * kCount);
  double worst_log = 0, worst_exp = 0, worst_atan = 0;
  for (std::size_t i = 0; i < kCount; ++i) {
    const dev::f4 x = a[i], y = b[i];
    volatile float p0 = x.x * y.x, p1 = x.y * y.y, p2 = x.z * y.z, p3 = x.w * y.w;
    volatile float dot3 = p0 + p1;
    dot3 = dot3 + p2;
    volatile float dot4 = dot3 + p3;
    volatile float dot2 = p0 + p1;
    volatile float xx = x.x * x.x, yy = x.y * x.y, zz = x.z * x.z;
    volatile float norm2 = xx + yy;
    norm2 = norm2 + zz;
    const float length = std::sqrt(static_cast<float>(norm2));
    volatile float c0a = x.y * y.z, c0b = x.z * y.y, c1a = x.z * y.x, c1b = x.x * y.z, c2a = x.x * y.y,
                   c2b = x.y * y.x;
    INFO("item " << i);
    const dev::f4 r0 = got[4 * i], r1 = got[4 * i + 1], r2 = got[4 * i + 2], r3 = got[4 * i + 3];
    REQUIRE(bits(r0.x) == bits(dot3));
    REQUIRE(bits(r0.y) == bits(length));
    REQUIRE(bits(r0.z) == bits(dot4));
    REQUIRE(bits(r0.w) == bits(dot2));
    REQUIRE(bits(r1.x) == bits(c0a - c0b));
    REQUIRE(bits(r1.y) == bits(c1a - c1b));
    REQUIRE(bits(r1.z) == bits(c2a - c2b));
    if (length > 0.0f) {
      REQUIRE(bits(r2.x) == bits(x.x / length));
      REQUIRE(bits(r2.y) == bits(x.y / length));
      REQUIRE(bits(r2.z) == bits(x.z / length));
    }
    worst_log = std::max(worst_log, ulps(r3.x, std::log2(static_cast<double>(x.w))));
    worst_exp = std::max(worst_exp, ulps(r3.y, std::exp2(static_cast<double>(y.w))));
    volatile float quotient = x.y / y.y;  // quotients from 1e-4 to 1e4, both signs
    worst_atan = std::max(worst_atan, ulps(r3.w, std::atan(static_cast<double>(quotient))));
    const double base = std::fabs(x.x), exponent = std::fabs(y.w);
    const double truth = base > 0 ? std::pow(base, exponent) : (exponent == 0 ? 1.0 : 0.0);
    // x^y = 2^t for t = y log2 x: a relative error e in t is an error of e |t| ln 2 in the result,
    // so log2's 2 ulp and the product's rounding allow about 1.5 |t| ulp beyond exp2's own 2.
    const double t = exponent * std::log2(std::max(base, 1e-30));
    const double allowance = 3.0 + 1.5 * std::fabs(t);
    if (std::fabs(t) < 126.0) {
      INFO("power(" << base << ", " << exponent << ") = " << r3.z << ", true " << truth);
      CHECK(ulps(r3.z, truth) <= allowance);
    }
  }
  CHECK(got[3].x == 0.0f);
  CHECK(got[4 * 2 + 3].y == 1.0f);
  CHECK(got[4 * 2 + 3].z == 1.0f);
  CHECK(got[4 * 3 + 3].y == std::numeric_limits<float>::denorm_min());
  CHECK(std::isinf(got[4 * 5 + 3].y));
  INFO("worst exact_log2 " << worst_log << " ulp, exact_exp2 " << worst_exp << " ulp, exact_atan "
                             << worst_atan << " ulp");
  CHECK(worst_log <= 2.0);
  CHECK(worst_exp <= 2.0);
  CHECK(worst_atan <= 2.0);
}

TEST_CASE("length3 and normalize3 keep vectors whose squares leave the float range",
          "[kernels][exact-math]") {
  // A triangle's normal at corners of 1e10 is 1e20 long, its square 1e40 beyond the floats; the
  // squares of components under 1e-19 lose their digits or vanish. Largest component 2^k, k
  // over both ends of the range, the others smaller.
  std::vector<dev::f4> a;
  for (int k = -140; k <= 127; k += 3)
    for (const dev::f4 shape : {dev::f4{1, 0, 0, 0}, dev::f4{-0.3f, 1, 0.7f, 0}, dev::f4{0.5f, -0.25f, -1, 0},
                                dev::f4{1, 1, 1, 0}})
      a.push_back({std::ldexp(shape.x, k), std::ldexp(shape.y, k), std::ldexp(shape.z, k), 1});
  const std::size_t count = a.size();
  const Global<dev::f4> out = allocate<dev::f4>(4 * count);
  run(test_program(kKernels), VectorMathArgs{upload(a), upload(a), static_cast<cl_uint>(count), out}, count);
  const std::vector<dev::f4> got = download(out, 4 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const double x = a[i].x, y = a[i].y, z = a[i].z;
    const double length = std::sqrt(x * x + y * y + z * z);
    INFO("(" << x << ", " << y << ", " << z << ")");
    if (length > std::numeric_limits<float>::max()) {
      CHECK(std::isinf(got[4 * i].y));  // the length itself exceeds the floats
    } else {
      CHECK(ulps(got[4 * i].y, length) <= 2.0);
    }
    const dev::f4 n = got[4 * i + 2];
    CHECK(ulps(n.x, x / length) <= 2.0);
    CHECK(ulps(n.y, y / length) <= 2.0);
    CHECK(ulps(n.z, z / length) <= 2.0);
  }
}
