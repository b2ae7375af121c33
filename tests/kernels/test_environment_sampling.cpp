// Path mode's environment samples (kernels/render/lights/environment.h) on the device against
// the host: a 16 x 8 map with a bright patch, a dark row and dark texels, turned by a rotation.
// A chi-square test compares the sampled directions with the density the host works out in
// double from the image (a texel's luminance times the sine at its row's centre, over the
// sphere's uv mapping's 2 pi^2 sin(theta)), and each sample's claimed density must be the
// host's for its direction; an escaping path claims the same (environment_density).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "geometry/geometry_data.hpp"
#include "render/frame_setup.hpp"
#include "sphere_chi_square.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const std::string kKernel = R"CL(
#define CLRT_TRANSPORT CLRT_MODE_PATH
#include "render/lights.h"
#include "render/random.h"

__kernel void draw_environment_samples(__global const Light* lights, uint environment, uint count,
                                       __global float4* directions, __global float4* densities) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float2 u = (float2)(uniform_float(hash_u32(2u * i + 1u)), uniform_float(hash_u32(2u * i + 2u)));
  __global const Light* light = &lights[environment];
  const LightSample s = sample_light(light, 0u, (float3)(0.3f, -1.0f, 2.0f), u);
  directions[i] = (float4)(s.to_light, s.distance);
  densities[i] = (float4)(s.density, s.geometry, environment_density(light, s.to_light), s.intensity.x);
}
)CL";

struct DrawEnvironmentSamplesArgs {
  static constexpr const char* kName = "draw_environment_samples";
  Global<const dev::Light> lights;
  cl_uint environment = 0;
  cl_uint count = 0;
  Global<dev::f4> directions, densities;
  CLRT_KERNEL_ARGS(lights, environment, count, directions, densities)
};

constexpr int kWidth = 16, kHeight = 8;
constexpr double kTurn = 35;  // degrees about (1, 2, 0.5)

// The map: a smooth sky, a bright patch, row 6 dark, and two dark texels in row 2.
std::vector<float> sky() {
  std::vector<float> rgb;
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      double r = 0.2 + 0.05 * i, g = 0.3 + 0.1 * j, b = 0.6;
      if (i >= 5 && i <= 6 && j >= 2 && j <= 3) r = g = b = 20;
      if (j == 6 || (j == 2 && (i == 0 || i == 9))) r = g = b = 0;
      rgb.insert(rgb.end(), {static_cast<float>(r), static_cast<float>(g), static_cast<float>(b)});
    }
  }
  return rgb;
}

// The host's density of the samples in world direction w.
struct HostDensity {
  Mat4 rotation;
  std::vector<double> weight;  // per texel: luminance times the sine at its row's centre
  double total = 0;

  HostDensity(const Mat4& r, const std::vector<float>& rgb) : rotation(r) {
    for (int j = 0; j < kHeight; ++j)
      for (int i = 0; i < kWidth; ++i) {
        const float* p = &rgb[3 * (j * kWidth + i)];
        weight.push_back((0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) * std::sin(kPi * (j + 0.5) / kHeight));
        total += weight.back();
      }
  }

  double operator()(V3 w) const {
    // The map's direction: the rotation's transpose times w.
    const Vec3 c0 = rotation.column(0), c1 = rotation.column(1), c2 = rotation.column(2);
    const double x = c0.x * w.x + c0.y * w.y + c0.z * w.z, y = c1.x * w.x + c1.y * w.y + c1.z * w.z,
                 z = c2.x * w.x + c2.y * w.y + c2.z * w.z;
    double u = std::atan2(x, -z) / (2 * kPi);
    if (u < 0) u += 1;
    const double v = std::acos(std::clamp(y, -1.0, 1.0)) / kPi;
    const int i = std::min(kWidth - 1, static_cast<int>(u * kWidth));
    const int j = std::min(kHeight - 1, static_cast<int>(v * kHeight));
    const double sin_theta = std::sqrt(x * x + z * z);
    return weight[static_cast<std::size_t>(j * kWidth + i)] / total * kWidth * kHeight / (2 * kPi * kPi * sin_theta);
  }
};

}  // namespace

TEST_CASE("path mode draws the environment by its luminance over the solid angle of its texels",
          "[kernels][path][lights]") {
  Scene scene;
  scene.materials.resize(1);
  EnvironmentSpec env;
  env.width = kWidth;
  env.height = kHeight;
  env.rgb = sky();
  env.scale = 1.5;
  env.rotation = Mat4::rotate(kTurn, {1, 2, 0.5});
  scene.environment = env;
  const GeometryData geometry = build_geometry(scene);
  RenderOptions options = RenderOptions::from_scene(scene);
  options.mode = RenderMode::Path;
  const FrameData frame = make_frame(scene, geometry, options);
  REQUIRE(frame.params.environment < frame.params.light_count);
  const std::vector<unsigned char> bytes = light_table_bytes(frame, geometry);
  const Global<const dev::Light> lights(device().allocate_copy(bytes.data(), bytes.size(), "light table"));

  const std::size_t count = device().device().platform().name() == "Oclgrind" ? 4000 : 200000;
  const Global<dev::f4> directions = allocate<dev::f4>(count), densities = allocate<dev::f4>(count);
  run(test_program(kKernel),
      DrawEnvironmentSamplesArgs{lights, frame.params.environment, static_cast<cl_uint>(count), directions,
                                 densities},
      count);
  const std::vector<dev::f4> dir = download(directions, count), dens = download(densities, count);

  const HostDensity host_density(env.rotation, env.rgb);
  const Frame f = frame_of(unit(V3{0.2, 1, -0.3}));
  std::vector<double> observed(kZBins * kPhiBins, 0.0), expected(kZBins * kPhiBins, 0.0);
  std::size_t off = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const V3 w = of(dir[i]);
    CHECK(std::isinf(dir[i].w));
    observed[static_cast<std::size_t>(bin_of(f, w))] += 1;
    const double density = host_density(w);
    INFO("sample " << i);
    CHECK(density > 0);  // never a dark texel
    CHECK(dens[i].z == dens[i].x);  // an escaping path claims the sample's density
    CHECK(dens[i].y == Approx(1 / dens[i].x).epsilon(1e-6));
    // Only a sample that rounding puts across a texel's edge may disagree with the host.
    if (!(dens[i].x == Approx(density).epsilon(1e-3))) ++off;
  }
  CHECK(off <= count / 2000);
  for_each_bin_point(f, 64, [&](int bin, V3 w, double d_omega) {
    expected[static_cast<std::size_t>(bin)] += host_density(w) * d_omega * count;
  });
  chi2_test(observed, expected);
}
