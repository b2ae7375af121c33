// Every row of the lobe table (CLRT_LOBES, kernels/render/lobes.h) on the device: a smooth lobe's
// sampled directions against the density the lobe itself reports, by a chi-square test over the
// sphere, so that a new lobe's sampling and density are held to each other the moment it has a
// row; a delta lobe draws a delta sample and reports no density.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "point_facing_kernel.hpp"
#include "sphere_chi_square.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const std::string kKernels = std::string(kPointFacingKernelCode) + R"CL(
#include "render/lobes.h"

/* out[0]: the number of lobes; out[1 + k]: whether lobe k is smooth. */
__kernel void lobe_rows(__global uint* out) {
  out[0] = CLRT_LOBE_COUNT;
  for (uint k = 0; k < CLRT_LOBE_COUNT; ++k) out[1u + k] = lobe_is_smooth(k) ? 1u : 0u;
}

/* The material's lobes with lobe k drawn every time. */
CLRT_INLINE PathLobes only_lobe(const Material* m, uint k) {
  PathLobes l = path_lobes(m);
  for (uint j = 0; j < CLRT_LOBE_COUNT; ++j) l.choice[j] = j == k ? 1.0f : 0.0f;
  return l;
}

/* Draw i from lobe k: out[i] = (direction, 0 none drawn, 1 smooth, 2 delta). */
__kernel void lobe_draws(uint k, __global const Material* material, float4 normal, float4 wo,
                         uint count, __global float4* out) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const ShadePoint sp = point_facing(normal, wo, material);
  const PathLobes l = only_lobe(&sp.material, k);
  const uint stream = hash_u32(i * 2654435761u + 977u);
  LobeSample s = smooth_sample((float3)(0.0f));
  const bool drawn = draw_lobe(&l, k, &sp.material, &sp, -wo.xyz, jitter2(stream, 0u),
                               jitter2(stream, 1u).x, &s);
  out[i] = (float4)(s.dir, drawn ? (s.smooth ? 1.0f : 2.0f) : 0.0f);
}

/* The density with which lobe k alone draws wi[i] (render/lobes.h, smooth_lobes). */
__kernel void lobe_densities(uint k, __global const Material* material, float4 normal, float4 wo,
                             uint count, __global const float4* wi, __global float* density) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const Material m = *material;
  const PathLobes l = only_lobe(&m, k);
  float pdf;
  smooth_lobes(&l, &m, normal.xyz, wo.xyz, wi[i].xyz, &pdf);
  density[i] = pdf;
}
)CL";

struct LobeRowsArgs {
  static constexpr const char* kName = "lobe_rows";
  Global<cl_uint> out;
  CLRT_KERNEL_ARGS(out)
};

struct LobeDrawsArgs {
  static constexpr const char* kName = "lobe_draws";
  cl_uint k = 0;
  Global<const dev::Material> material;
  dev::f4 normal, wo;
  cl_uint count = 0;
  Global<dev::f4> out;
  CLRT_KERNEL_ARGS(k, material, normal, wo, count, out)
};

struct LobeDensitiesArgs {
  static constexpr const char* kName = "lobe_densities";
  cl_uint k = 0;
  Global<const dev::Material> material;
  dev::f4 normal, wo;
  cl_uint count = 0;
  Global<const dev::f4> wi;
  Global<float> density;
  CLRT_KERNEL_ARGS(k, material, normal, wo, count, wi, density)
};

dev::f4 f4_of(V3 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0};
}

bool under_oclgrind() { return device().device().platform().name() == "Oclgrind"; }

struct Lobes {
  std::vector<bool> smooth;  // by lobe, in the table's order
};

Lobes lobe_rows() {
  constexpr std::size_t kMost = 64;
  const Global<cl_uint> out = allocate<cl_uint>(kMost + 1);
  run(test_program(kKernels), LobeRowsArgs{out}, 1);
  const std::vector<cl_uint> rows = download(out, kMost + 1);
  REQUIRE(rows[0] >= 1);
  REQUIRE(rows[0] <= kMost);
  Lobes lobes;
  for (cl_uint k = 0; k < rows[0]; ++k) lobes.smooth.push_back(rows[1 + k] != 0);
  return lobes;
}

// A white material every lobe has a share of: Lambertian, Phong (exponent n), mirror and glass.
dev::Material every_lobe(float exponent) { return {{1, 1, 1, 0}, 0, 0.5f, 0.5f, exponent, 0.2f, 0.2f, 1.5f, 0, {0, 0, 0, 0}, {}}; }

}  // namespace

TEST_CASE("every lobe of the table draws directions with the density it reports", "[kernels][path]") {
  const Lobes lobes = lobe_rows();
  const V3 n = unit(V3{0.3, 1.0, -0.2}), wo = unit(V3{0.4, 0.8, 0.3});
  const Frame f = frame_of(n);
  const std::size_t samples = under_oclgrind() ? 3000 : 200000;
  const int sub = under_oclgrind() ? 4 : 12;  // midpoints per bin and axis for the density
  std::vector<dev::f4> points;
  std::vector<int> point_bin;
  std::vector<double> point_weight;
  for_each_bin_point(f, sub, [&](int bin, V3 w, double d_omega) {
    points.push_back(f4_of(w));
    point_bin.push_back(bin);
    point_weight.push_back(d_omega);
  });
  const Global<const dev::f4> wi = upload(points);
  for (float exponent : {0.0f, 20.0f}) {
    const Global<const dev::Material> material = upload(std::vector<dev::Material>{every_lobe(exponent)});
    for (cl_uint k = 0; k < lobes.smooth.size(); ++k) {
      INFO("lobe " << k << " of the table, Phong exponent " << exponent);
      const Global<dev::f4> draws = allocate<dev::f4>(samples);
      run(test_program(kKernels),
          LobeDrawsArgs{k, material, f4_of(n), f4_of(wo), static_cast<cl_uint>(samples), draws}, samples);
      const std::vector<dev::f4> drawn = download(draws, samples);
      const Global<float> density = allocate<float>(points.size());
      run(test_program(kKernels),
          LobeDensitiesArgs{k, material, f4_of(n), f4_of(wo), static_cast<cl_uint>(points.size()), wi, density},
          points.size());
      const std::vector<float> pdf = download(density, points.size());
      if (!lobes.smooth[k]) {
        std::size_t not_delta = 0;
        for (const dev::f4& d : drawn) not_delta += d.w != 2.0f;
        CHECK(not_delta == 0);
        double mass = 0;
        for (float p : pdf) mass += p;
        CHECK(mass == 0);  // a delta lobe has no density for a pair of directions
        continue;
      }
      // Bins over the sphere, and one more for draws below the surface, where a smooth lobe
      // reports no density: the expected count there is what its density leaves of 1.
      const std::size_t below = kZBins * kPhiBins;
      std::vector<double> expected(below + 1, 0.0), observed(below + 1, 0.0);
      double covered = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        expected[point_bin[i]] += pdf[i] * point_weight[i] * samples;
        covered += pdf[i] * point_weight[i];
      }
      CHECK(covered <= 1.01);
      expected[below] = std::max(0.0, 1 - covered) * samples;
      std::size_t not_smooth = 0;
      for (const dev::f4& d : drawn) {
        not_smooth += d.w != 1.0f;
        const V3 w = unit(of(d));
        observed[dot(n, w) > 0 ? bin_of(f, w) : below] += 1;
      }
      CHECK(not_smooth == 0);
      chi2_test(observed, expected);
    }
  }
}
