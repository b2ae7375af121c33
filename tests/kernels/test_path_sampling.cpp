// Path mode's sampling (kernels/render/lobes.h, sample_lobes) on the device against the
// densities it claims, as Mitsuba 3's chi2 tests do: directions binned over the sphere against
// the density integrated over each bin on the host in double, pooled where fewer than 5 are
// expected, and a chi-square test; the dielectric's choice between reflection and refraction
// against the Fresnel equations; and each sample's weight against f cos / pdf.
#include <catch2/catch.hpp>

#include <algorithm>
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
#include "render/path_step.h"

/* Sample i continues a path arriving along -wo at a surface with normal n (front side). */
__kernel void draw_continuations(__global const Material* material, float4 normal, float4 wo, uint count,
                           __global float4* directions, __global float4* weights) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const ShadePoint sp = point_facing(normal, wo, material);
  Ray ray;
  vstore3((float3)(0.0f), 0, ray.origin);
  ray.radiance_scale = 1.0f;
  vstore3(-wo.xyz, 0, ray.dir);
  ray.sample_cone = 0u;
  vstore3((float3)(1.0f), 0, ray.weight);
  ray.pdf = 0.0f;
  ray.sample = i;
  ray.depth_kind = CLRT_DEPTH_KIND(1u, CLRT_RAY_REFLECTION);
  ray.path = hash_u32(i * 2654435761u + 12345u);
  ray.time = 0.0f;
  const PathLobes lobes = path_lobes(&sp.material);
  LobeSample s = smooth_sample((float3)(0.0f)); /* what a path that ends before a draw shows */
  float pdf;
  const float2 choice = path_sample(&ray, CLRT_PATH_CHOICE);
  const bool goes_on = sample_lobes(&lobes, &sp.material, &sp, -wo.xyz,
                                    path_sample(&ray, CLRT_PATH_DIRECTION), choice.x, &s, &pdf);
  /* A path that ends still shows the direction its lobe drew (below the surface, say). */
  directions[i] = (float4)(s.dir, goes_on ? (float)s.kind : -1.0f);
  weights[i] = (float4)(s.weight, pdf);
}

/* Samples 0 .. count - 1 of the pair `key`. */
__kernel void sobol_points(uint key, uint count, __global float4* points) {
  const uint i = get_global_id(0);
  if (i < count) points[i] = (float4)(sobol_sample(key, i), 0.0f, 0.0f);
}
)CL";

struct SobolPointsArgs {
  static constexpr const char* kName = "sobol_points";
  cl_uint key = 0, count = 0;
  Global<dev::f4> points;
  CLRT_KERNEL_ARGS(key, count, points)
};

struct DrawContinuationsArgs {
  static constexpr const char* kName = "draw_continuations";
  Global<const dev::Material> material;
  dev::f4 normal, wo;
  cl_uint count = 0;
  Global<dev::f4> directions, weights;
  CLRT_KERNEL_ARGS(material, normal, wo, count, directions, weights)
};


// White, ka 0.
dev::Material material(float kd, float ks, float n, float kr, float kt, float ior = 1.5f) {
  return {{1, 1, 1, 0}, 0, kd, ks, n, kr, kt, ior, 0, {0, 0, 0, 0}, {}};
}

// The density with which the smooth lobes draw wi, as docs/path-tracing.md states it, over the
// whole sphere (the Phong lobe's part below the surface included: those samples end the path).
struct SmoothDensity {
  double p_diffuse, p_glossy, exponent;
  V3 n, mirror;
  double operator()(V3 wi) const {
    const double cos_i = dot(n, wi), cos_a = dot(mirror, wi);
    // Exponent 0 is a Lambertian lobe, drawn by cosine.
    const double glossy = exponent == 0 ? std::max(0.0, cos_i) / kPi
                                        : (exponent + 1) / (2 * kPi) * std::pow(std::max(0.0, cos_a), exponent);
    return p_diffuse * std::max(0.0, cos_i) / kPi + p_glossy * glossy;
  }
};


struct Samples {
  std::vector<dev::f4> directions, weights;
};

Samples sample(const dev::Material& m, V3 n, V3 wo, std::size_t count) {
  const Global<dev::f4> directions = allocate<dev::f4>(count), weights = allocate<dev::f4>(count);
  const dev::f4 normal{static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z), 0};
  const dev::f4 view{static_cast<float>(wo.x), static_cast<float>(wo.y), static_cast<float>(wo.z), 0};
  run(test_program(kKernels),
      DrawContinuationsArgs{upload(std::vector<dev::Material>{m}), normal, view, static_cast<cl_uint>(count),
                      directions, weights},
      count);
  return {download(directions, count), download(weights, count)};
}

std::size_t sample_count() {
  // Oclgrind interprets every instruction: fewer samples (the test stays as strict).
  return device().device().platform().name() == "Oclgrind" ? 3000 : 400000;
}

}  // namespace

TEST_CASE("path mode draws smooth-lobe directions with the density it claims", "[kernels][path]") {
  const V3 n = unit(V3{0.3, 1.0, -0.2});
  struct Case {
    const char* what;
    dev::Material m;
    V3 wo;
  };
  for (const Case& c : {Case{"Lambertian", material(1, 0, 1, 0, 0), unit(V3{0.2, 1, 0.5})},
                        Case{"Phong, exponent 0", material(0, 1, 0, 0, 0), unit(V3{0.6, 0.7, 0.1})},
                        Case{"Lambertian and Phong, exponent 0", material(0.3, 0.7, 0, 0, 0), unit(V3{-0.6, 0.3, 0.4})},
                        Case{"Phong, exponent 1", material(0, 1, 1, 0, 0), unit(V3{0.6, 0.7, 0.1})},
                        Case{"Phong, exponent 30", material(0, 1, 30, 0, 0), unit(V3{-0.5, 0.8, 0.3})},
                        Case{"Phong, exponent 300", material(0, 1, 300, 0, 0), unit(V3{0.1, 0.9, -0.6})},
                        Case{"Lambertian and Phong", material(0.6, 0.4, 12, 0, 0), unit(V3{0.7, 0.4, 0.2})}}) {
    INFO(c.what);
    const double kd = c.m.kd, ks = c.m.ks;
    const V3 wo = unit(c.wo);
    const SmoothDensity density{kd / (kd + ks), ks / (kd + ks), c.m.shininess, n,
                                2 * dot(n, wo) * n + (-1.0) * wo};
    const Frame f = frame_of(n);
    const std::size_t count = sample_count();
    const Samples s = sample(c.m, n, wo, count);
    std::vector<double> observed(kZBins * kPhiBins, 0.0);
    double worst_weight = 0, worst_pdf = 0;
    std::size_t ended_above = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const V3 wi = unit(of(s.directions[i]));
      observed[bin_of(f, wi)] += 1;
      if (s.directions[i].w < 0) {
        if (dot(n, wi) > 1e-6) ++ended_above;  // only a direction below the surface ends the path
        continue;
      }
      // The weight is f cos / pdf for both lobes together, whichever drew the direction.
      const double cos_i = dot(n, wi);
      const double brdf = kd / kPi + ks * (c.m.shininess + 2) / (2 * kPi) *
                                      std::pow(std::max(0.0, dot(2 * cos_i * n + (-1.0) * wi, wo)),
                                               c.m.shininess);
      const double expected = brdf * cos_i / density(wi);
      // Relative, but absolute near the horizon, where float cosines lose their digits.
      worst_weight = std::max(worst_weight, std::fabs(s.weights[i].x - expected) / (expected + 1e-2));
      worst_pdf = std::max(worst_pdf, std::fabs(s.weights[i].w - density(wi)) / (density(wi) + 1e-2));
    }
    CHECK(ended_above == 0);
    CHECK(worst_weight < 1e-3);
    CHECK(worst_pdf < 1e-3);
    std::vector<double> expected = bin_probabilities(f, density);
    for (double& e : expected) e *= static_cast<double>(count);
    chi2_test(observed, expected);
  }
}

TEST_CASE("path mode's dielectric reflects with the Fresnel equations' probability", "[kernels][path]") {
  const V3 n{0, 1, 0};
  for (const bool outside : {true, false}) {
    for (const double degrees : {0.0, 30.0, 60.0, 80.0, 89.0}) {
      INFO((outside ? "entering" : "leaving") << " glass at " << degrees << " degrees");
      const double theta = degrees * kPi / 180;
      const V3 wo{std::sin(theta), std::cos(theta), 0};
      // Leaving: the same geometry seen from inside, where the index ratio is the inverse.
      const double eta = outside ? 1 / 1.5 : 1.5;
      const dev::Material m = material(0, 0, 1, 0, 1, outside ? 1.5f : 1.0f / 1.5f);
      const double cos_i = std::cos(theta), sin2_t = eta * eta * (1 - cos_i * cos_i);
      double reflectance = 1;
      if (sin2_t < 1) {
        const double cos_t = std::sqrt(1 - sin2_t);
        const double rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
        const double rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
        reflectance = 0.5 * (rs * rs + rp * rp);
      }
      const std::size_t count = sample_count();
      const Samples s = sample(m, n, wo, count);
      double reflected = 0;
      std::size_t wrong = 0;
      for (std::size_t i = 0; i < count; ++i) {
        const V3 wi = of(s.directions[i]);
        if (s.directions[i].w == static_cast<float>(CLRT_RAY_REFLECTION)) {
          reflected += 1;
          wrong += std::fabs(dot(wi, V3{-wo.x, wo.y, 0}) - 1) > 1e-5 || s.weights[i].x != 1.0f;
        } else {
          // Snell's law, and radiance scaled by (n_i / n_t)^2.
          wrong += std::fabs(std::fabs(wi.x) - eta * std::sin(theta)) > 1e-5 ||
                   std::fabs(s.weights[i].x - eta * eta) > 1e-5 * eta * eta;
        }
      }
      CHECK(wrong == 0);
      const double total = static_cast<double>(count);
      if (reflectance == 1) {
        CHECK(reflected == total);
      } else {
        // A binomial count: within 3.3 standard deviations (p > 0.001, two-sided).
        const double z = (reflected - reflectance * total) /
                         std::sqrt(total * reflectance * (1 - reflectance));
        INFO("reflected " << reflected << " of " << total << ", Fresnel " << reflectance << ", z " << z);
        CHECK(std::fabs(z) < 3.3);
      }
    }
  }
}

namespace {

// 1 - cos of the angle between unit vectors a and b, with its digits near 0.
double one_minus_cos(V3 a, V3 b) {
  const V3 d = a + (-1.0) * b;
  return 0.5 * dot(d, d);
}

// The Phong lobe's directional albedo for light leaving along wo, integrated on the host in
// double: over the lobe's own parametrisation (cos a = v^(1 / (n + 1)) about the mirror
// direction R, v uniform, which carries the density (n + 1) / (2 pi) cos^n a), the BSDF over the
// density times the cosine at the surface is (n + 2) / (n + 1) max(0, N.wi). Midpoint rule.
double phong_albedo(V3 n, V3 wo, double exponent) {
  const V3 r = 2 * dot(n, wo) * n + (-1.0) * wo;
  const Frame f = frame_of(r);
  constexpr int kV = 1000, kPhi = 200;
  double sum = 0;
  for (int i = 0; i < kV; ++i) {
    const double v = (i + 0.5) / kV;
    const double delta = -std::expm1(std::log(v) / (exponent + 1));  // 1 - cos a
    const double cos_a = 1 - delta, sin_a = std::sqrt(delta * (2 - delta));
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kPhi;
      const V3 wi = cos_a * f.n + (sin_a * std::cos(phi)) * f.t + (sin_a * std::sin(phi)) * f.b;
      sum += std::max(0.0, dot(n, wi));
    }
  }
  return (exponent + 2) / (exponent + 1) * sum / (double{kV} * kPhi);
}

// The mean of the samples' weights (0 where the path ends), with its standard error.
struct Mean {
  double value, error;
};

Mean mean_weight(const Samples& s) {
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < s.weights.size(); ++i) {
    const double w = s.directions[i].w < 0 ? 0.0 : s.weights[i].x;
    sum += w;
    sum2 += w * w;
  }
  const double n = static_cast<double>(s.weights.size()), mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

}  // namespace

TEST_CASE("the Phong lobe draws cos^n about the mirror direction at any exponent",
          "[kernels][path]") {
  // Binned in the lobe's own coordinates, v = cos^(n + 1) a and the azimuth about the mirror
  // direction, where every bin expects the same count: a grid over the sphere cannot resolve a
  // lobe of exponent 1e6 (a thousandth of a radian wide), whose directions collapsed onto the
  // axis while 1 - cos was taken from a cosine rounded to float.
  const V3 n = unit(V3{-0.2, 1.0, 0.4});
  const V3 wo = unit(V3{0.3, 0.9, -0.2});
  const V3 r = 2 * dot(n, wo) * n + (-1.0) * wo;
  const Frame f = frame_of(r);
  constexpr int kVBins = 10, kAzimuthBins = 16;
  for (const double exponent : {1.0, 10.0, 100.0, 1e4, 1e6}) {
    INFO("exponent " << exponent);
    const std::size_t count = sample_count();
    const Samples s = sample(material(0, 1, static_cast<float>(exponent), 0, 0), n, wo, count);
    std::vector<double> observed(kVBins * kAzimuthBins, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
      const V3 wi = unit(of(s.directions[i]));
      const double delta = one_minus_cos(r, wi);
      const double v = std::exp((exponent + 1) * std::log1p(-delta));
      const double phi = std::atan2(dot(f.b, wi), dot(f.t, wi));
      const int vi = std::min(kVBins - 1, static_cast<int>(v * kVBins));
      const int ai = std::min(kAzimuthBins - 1, static_cast<int>((phi + kPi) / (2 * kPi) * kAzimuthBins));
      observed[vi * kAzimuthBins + ai] += 1;
    }
    chi2_test(observed, std::vector<double>(observed.size(), static_cast<double>(count) / observed.size()));
  }
}

TEST_CASE("a furnace per lobe: the mean weight of a continuation is the lobe's albedo",
          "[kernels][path]") {
  // Seen along the normal every smooth lobe reflects all it receives: a mean weight of 1 within
  // noise (exactly 1 where the weight does not vary). Seen obliquely, part of a Phong lobe lies
  // below the surface: the mean is the albedo integrated on the host.
  const V3 n = unit(V3{0.1, 1.0, 0.2});
  struct Case {
    const char* what;
    dev::Material m;
  };
  for (const Case& c : {Case{"Lambertian", material(1, 0, 1, 0, 0)},
                        Case{"Phong, exponent 0", material(0, 1, 0, 0, 0)},
                        Case{"Phong, exponent 1", material(0, 1, 1, 0, 0)},
                        Case{"Phong, exponent 10", material(0, 1, 10, 0, 0)},
                        Case{"Phong, exponent 1e4", material(0, 1, 1e4f, 0, 0)},
                        Case{"Phong, exponent 1e8", material(0, 1, 1e8f, 0, 0)},
                        Case{"Lambertian and Phong, exponent 0", material(0.5, 0.5, 0, 0, 0)},
                        Case{"Lambertian and Phong, exponent 50", material(0.5, 0.5, 50, 0, 0)},
                        Case{"mirror", material(0, 0, 1, 1, 0)}}) {
    INFO(c.what);
    const Mean m = mean_weight(sample(c.m, n, n, sample_count()));
    INFO("mean weight " << m.value << " +- " << m.error);
    CHECK(std::fabs(m.value - 1) <= 4 * m.error + 1e-6);
  }
  for (const double exponent : {0.0, 1.0, 5.0, 40.0, 1e4}) {
    for (const double degrees : {30.0, 70.0, 85.0}) {
      const double theta = degrees * kPi / 180;
      const V3 wo = unit(std::cos(theta) * n + std::sin(theta) * frame_of(n).t);
      const double albedo = exponent == 0 ? 1.0 : phong_albedo(n, wo, exponent);
      const Mean m = mean_weight(sample(material(0, 1, static_cast<float>(exponent), 0, 0), n, wo, sample_count()));
      INFO("exponent " << exponent << " at " << degrees << " degrees: mean weight " << m.value
                       << " +- " << m.error << ", albedo " << albedo);
      CHECK(std::fabs(m.value - albedo) <= 4 * m.error + 1e-4);
    }
  }
}

TEST_CASE("any exponent the reader accepts gives finite weights and densities", "[kernels][path]") {
  const V3 n = unit(V3{0.3, 1.0, -0.2});
  for (const float exponent : {0.0f, 1e-6f, 1e6f, 1e9f, 1e12f}) {
    for (const V3 wo : {n, unit(V3{0.6, 0.7, 0.1}), unit(V3{1.0, 0.01, 0.0})}) {
      INFO("exponent " << exponent);
      const Samples s = sample(material(0.2f, 0.8f, exponent, 0, 0), n, wo, sample_count() / 20);
      std::size_t bad = 0;
      for (std::size_t i = 0; i < s.weights.size(); ++i)
        if (s.directions[i].w >= 0)
          bad += !(std::isfinite(s.weights[i].x) && std::isfinite(s.weights[i].w) && s.weights[i].w > 0);
      CHECK(bad == 0);
    }
  }
}

TEST_CASE("a pixel's first 2^m Sobol samples of any pair form a (0, m, 2)-net", "[kernels][path]") {
  // Every elementary interval of area 2^-m (2^a columns by 2^(m - a) rows, for each a) holds
  // exactly one of them: stratified in x, in y and in every shape between, however scrambled.
  for (const cl_uint key : {0u, 1u, 0x9e3779b9u, 123456789u}) {
    for (const int m : {2, 5, 8}) {
      const cl_uint count = 1u << m;
      const Global<dev::f4> points = allocate<dev::f4>(count);
      run(test_program(kKernels), SobolPointsArgs{key, count, points}, count);
      const std::vector<dev::f4> p = download(points, count);
      for (int a = 0; a <= m; ++a) {
        INFO("key " << key << ", 2^" << m << " samples, intervals of " << (1 << a) << " x " << (1 << (m - a)));
        std::vector<int> hits(count, 0);
        for (const dev::f4& q : p) {
          REQUIRE((q.x >= 0 && q.x < 1 && q.y >= 0 && q.y < 1));
          const int column = static_cast<int>(q.x * (1 << a)), row = static_cast<int>(q.y * (1 << (m - a)));
          ++hits[row * (1 << a) + column];
        }
        CHECK(std::count(hits.begin(), hits.end(), 1) == static_cast<long>(count));
      }
    }
  }
}

TEST_CASE("different pairs' Sobol samples are not correlated", "[kernels][path]") {
  // Two keys' 4096 points, paired sample by sample: their x coordinates' correlation is that of
  // independent numbers (within 4 standard errors, 4 / sqrt(4096)), as the shuffled indices give.
  const cl_uint count = 4096;
  const auto points_of = [&](cl_uint key) {
    const Global<dev::f4> points = allocate<dev::f4>(count);
    run(test_program(kKernels), SobolPointsArgs{key, count, points}, count);
    return download(points, count);
  };
  const std::vector<dev::f4> a = points_of(17u), b = points_of(18u);
  double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
  for (cl_uint i = 0; i < count; ++i) {
    const double x = a[i].x, y = b[i].x;
    sa += x, sb += y, sab += x * y, saa += x * x, sbb += y * y;
  }
  const double n = count;
  const double r = (sab / n - sa / n * sb / n) /
                   std::sqrt((saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n));
  INFO("correlation " << r);
  CHECK(std::fabs(r) < 4 / std::sqrt(n));
}
