// The texture lookups of kernels/render/texture.h launched alone on hand-made textures, against
// the host's own arithmetic in double: bilinear filtering with both wrappings, the mip level a
// footprint picks and the blend between two, the checkerboard's box-filtered average (against
// numerical integration), and the properties of noise that follow from its definition.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "cl_fixture.hpp"
#include "render/texture_table.hpp"
#include "scene/scene_image.hpp"

using namespace clrt;
using namespace clrt::test;

namespace texture_kernel_test {

const std::string kKernel = R"CL(
#include "render/texture.h"

__kernel void texture_values(__global const Texture* textures, __global const uint* texels,
                             __global const uint* which, __global const float4* queries, uint count,
                             __global float4* values) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float4 q = queries[i];
  values[i] = (float4)(texture_value(textures + which[i], texels, q.x, q.y, q.z), 0.0f);
}
)CL";

struct TextureValuesArgs {
  static constexpr const char* kName = "texture_values";
  Global<const dev::Texture> textures;
  Global<const cl_uint> texels;
  Global<const cl_uint> which;
  Global<const dev::f4> queries;
  cl_uint count = 0;
  Global<dev::f4> values;
  CLRT_KERNEL_ARGS(textures, texels, which, queries, count, values)
};

struct Query {
  cl_uint texture;
  float u, v, width;
};

using Rgb = std::array<double, 3>;

// The device's value of each query on the scene's textures.
std::vector<Rgb> device_values(const Scene& scene, const std::vector<Query>& queries) {
  const TextureTable table = make_texture_table(scene);
  std::vector<cl_uint> which;
  std::vector<dev::f4> q;
  for (const Query& x : queries) {
    which.push_back(texture_row(static_cast<int>(x.texture)));
    q.push_back({x.u, x.v, x.width, 0});
  }
  const auto count = static_cast<cl_uint>(queries.size());
  const Global<dev::f4> values = allocate<dev::f4>(count);
  run(test_program(kKernel),
      TextureValuesArgs{upload(table.records), upload(std::vector<cl_uint>(table.texels.begin(), table.texels.end())),
                        upload(which), upload(q), count, values},
      count);
  std::vector<Rgb> out;
  for (const dev::f4& v : download(values, count)) out.push_back({v.x, v.y, v.z});
  return out;
}

// A level of an image in linear values, rows from the bottom (t = 0) up.
struct HostLevel {
  int width, height;
  std::vector<Rgb> texels;
  const Rgb& at(int x, int y) const { return texels[static_cast<std::size_t>(y * width + x)]; }
};

HostLevel host_level(const TextureImage& image) {
  HostLevel l{image.width, image.height, {}};
  for (int y = image.height - 1; y >= 0; --y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = 3 * static_cast<std::size_t>(y * image.width + x);
      Rgb t;
      for (std::size_t c = 0; c < 3; ++c)
        t[c] = image.linear ? image.rgb[i + c] : std::pow((image.srgb[i + c] / 255.0 + 0.055) / 1.055, 2.4);
      if (!image.linear)
        for (std::size_t c = 0; c < 3; ++c)
          if (image.srgb[i + c] / 255.0 <= 0.04045) t[c] = image.srgb[i + c] / 255.0 / 12.92;
      l.texels.push_back(t);
    }
  return l;
}

HostLevel halved(const HostLevel& fine) {
  HostLevel c{std::max(fine.width / 2, 1), std::max(fine.height / 2, 1), {}};
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      Rgb sum{0, 0, 0};
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          for (std::size_t k = 0; k < 3; ++k)
            sum[k] += fine.at(std::min(2 * x + dx, fine.width - 1), std::min(2 * y + dy, fine.height - 1))[k] / 4;
      c.texels.push_back(sum);
    }
  return c;
}

// Bilinear at (s, t) with texel centres at (i + 0.5) / size, by the wrapping.
Rgb bilinear(const HostLevel& l, double s, double t, bool clamp) {
  const auto index = [&](long i, int n) {
    if (clamp) return static_cast<int>(std::min<long>(std::max<long>(i, 0), n - 1));
    return static_cast<int>(((i % n) + n) % n);
  };
  if (clamp) {
    s = std::min(std::max(s, 0.0), 1.0);
    t = std::min(std::max(t, 0.0), 1.0);
  }
  const double x = s * l.width - 0.5, y = t * l.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
  Rgb out{};
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const Rgb& v = l.at(index(static_cast<long>(x0) + dx, l.width), index(static_cast<long>(y0) + dy, l.height));
      const double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
      for (std::size_t k = 0; k < 3; ++k) out[k] += w * v[k];
    }
  return out;
}

void check_close(const Rgb& got, const Rgb& want, double margin) {
  for (std::size_t k = 0; k < 3; ++k) CHECK(got[k] == Approx(want[k]).margin(margin));
}

TextureSpec image_texture(int image, bool clamp = false) {
  TextureSpec t;
  t.image = image;
  t.clamp = clamp;
  return t;
}

TEST_CASE("an 8-bit image is read bilinearly at level 0, repeating or clamped, right way up",
          "[kernels][texture]") {
  Scene scene;
  TextureImage image;  // 3 x 2, rows from the top
  image.width = 3;
  image.height = 2;
  image.srgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30, 128, 128, 128, 250, 200, 100};
  scene.texture_images.push_back(image);
  scene.textures = {image_texture(0), image_texture(0, true)};
  std::vector<Query> queries;
  const float points[][2] = {{0.5f, 0.5f}, {1 / 6.0f, 0.75f}, {0.01f, 0.02f}, {0.99f, 0.97f}, {-0.3f, 1.7f},
                             {2.4f, -0.6f}, {0.8333f, 0.25f}, {0.6f, 0.1f}};
  for (cl_uint t = 0; t < 2; ++t)
    for (const auto& p : points) queries.push_back({t, p[0], p[1], 0});
  const std::vector<Rgb> got = device_values(scene, queries);
  const HostLevel level = host_level(image);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    INFO("texture " << queries[i].texture << " at (" << queries[i].u << ", " << queries[i].v << ")");
    check_close(got[i], bilinear(level, queries[i].u, queries[i].v, queries[i].texture == 1), 2e-6);
  }
  // The top left texel (red) is at (u, v) = (1/6, 3/4): v = 0 is the image's bottom row.
  check_close(got[1], {1, 0, 0}, 1e-6);
}

TEST_CASE("a footprint picks the mip level of its size, blending two between powers of two",
          "[kernels][texture]") {
  Scene scene;
  TextureImage image;  // 4 x 4 linear values
  image.width = image.height = 4;
  image.linear = true;
  for (int i = 0; i < 16; ++i) image.rgb.insert(image.rgb.end(), {i * 0.0625f, (i % 3) * 0.5f, i % 4 == 0 ? 2.0f : 0.25f});
  scene.texture_images.push_back(image);
  scene.textures = {image_texture(0)};
  const HostLevel l0 = host_level(image), l1 = halved(l0), l2 = halved(l1);
  // texels across = width * 4: level = log2 of that.
  const float s = 0.3f, t = 0.6f;
  const std::vector<Query> queries = {{0, s, t, 0.1f},   {0, s, t, 0.25f}, {0, s, t, 0.5f},
                                      {0, s, t, 0.3535534f}, {0, s, t, 1.0f},  {0, s, t, 100.0f}};
  const std::vector<Rgb> got = device_values(scene, queries);
  check_close(got[0], bilinear(l0, s, t, false), 2e-6);  // under a texel
  check_close(got[1], bilinear(l0, s, t, false), 2e-6);  // one texel
  check_close(got[2], bilinear(l1, s, t, false), 2e-6);  // two: level 1
  Rgb half;
  for (std::size_t k = 0; k < 3; ++k) half[k] = 0.5 * bilinear(l0, s, t, false)[k] + 0.5 * bilinear(l1, s, t, false)[k];
  check_close(got[3], half, 2e-5);                       // 2^1.5 texels: halfway
  check_close(got[4], bilinear(l2, s, t, false), 2e-6);  // four: the 1x1 level, the mean
  check_close(got[5], bilinear(l2, s, t, false), 2e-6);  // beyond the last level
  check_close(got[4], {0.46875, 0.46875, 0.6875}, 1e-6);
}

TEST_CASE("scale and offset move the texture's coordinates and widen its footprint", "[kernels][texture]") {
  Scene scene;
  TextureImage image;
  image.width = 4;
  image.height = 2;
  image.linear = true;
  for (int i = 0; i < 8; ++i) image.rgb.insert(image.rgb.end(), {i * 0.125f, 1 - i * 0.125f, 0.5f});
  scene.texture_images.push_back(image);
  TextureSpec moved = image_texture(0);
  moved.scale[0] = 2;
  moved.scale[1] = 0.5;
  moved.offset[0] = 0.25;
  moved.offset[1] = -0.5;
  scene.textures = {image_texture(0), moved};
  const std::vector<Query> queries = {{1, 0.1f, 0.7f, 0.05f}, {0, 0.45f, -0.15f, 0.05f}};
  const std::vector<Rgb> got = device_values(scene, queries);
  check_close(got[0], got[1], 1e-6);  // the same point, the same footprint (sqrt(2 x 0.5) = 1)
}

double checker_sign(double s, double t) {
  return (static_cast<long long>(std::floor(s)) + static_cast<long long>(std::floor(t))) % 2 == 0 ? 1 : -1;
}

TEST_CASE("the checkerboard is point-sampled for a tiny footprint and box-filtered for a larger one",
          "[kernels][texture]") {
  Scene scene;
  TextureSpec checker;
  checker.kind = TextureSpec::Kind::Checker;
  checker.color0 = {1, 0.5, 0};
  checker.color1 = {0, 0.5, 1};
  scene.textures = {checker};
  const std::vector<Query> queries = {{0, 0.3f, 0.3f, 0},     {0, 1.3f, 0.3f, 0},     {0, -0.3f, 0.3f, 0},
                                      {0, -2.7f, -5.2f, 0},   {0, 0.5f, 0.5f, 0.5f},  {0, 0.9f, 0.2f, 0.5f},
                                      {0, 1.0f, 1.0f, 1.0f},  {0, 0.7f, 2.9f, 1.3f},  {0, 10.25f, 3.1f, 3.7f},
                                      {0, 0.2f, 0.6f, 40.5f}};
  const std::vector<Rgb> got = device_values(scene, queries);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    double mean = checker_sign(q.u, q.v);
    if (q.width > 0) {
      // The sign's average over the footprint, by the midpoint rule on 600 x 600 points.
      const int n = 600;
      double sum = 0;
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a)
          sum += checker_sign(q.u + q.width * ((a + 0.5) / n - 0.5), q.v + q.width * ((b + 0.5) / n - 0.5));
      mean = sum / (n * n);
    }
    INFO("query " << i);
    const double w0 = 0.5 + 0.5 * mean;
    check_close(got[i], {w0, 0.5, 1 - w0}, 4e-3);
  }
}

TEST_CASE("noise lies between its colours, is 0 (their middle) on the lattice and for a footprint of a cell, "
          "and varies smoothly",
          "[kernels][texture]") {
  Scene scene;
  TextureSpec noise;
  noise.kind = TextureSpec::Kind::Noise;
  noise.color0 = {0, 0, 0};
  noise.color1 = {1, 2, 4};
  noise.octaves = 5;
  scene.textures = {noise};
  std::vector<Query> queries = {{0, 3, -7, 0}, {0, 0, 0, 0}, {0, 0.37f, 0.81f, 0.5f}, {0, 12.3f, 4.56f, 7.0f}};
  for (int i = 0; i < 400; ++i) {
    const float s = 0.173f * i, t = 0.311f * i - 20;
    queries.push_back({0, s, t, 0});
    queries.push_back({0, s + 1e-3f, t, 0});
  }
  const std::vector<Rgb> got = device_values(scene, queries);
  for (std::size_t i = 0; i < 4; ++i) check_close(got[i], {0.5, 1, 2}, 1e-6);
  double sum = 0, squares = 0, largest_step = 0;
  for (std::size_t i = 4; i < got.size(); i += 2) {
    const double a = got[i][0];
    CHECK(a >= 0);
    CHECK(a <= 1);
    CHECK(got[i][1] == Approx(2 * a).margin(1e-6));
    sum += a;
    squares += a * a;
    largest_step = std::max(largest_step, std::fabs(got[i + 1][0] - a));
  }
  const double mean = sum / 400, spread = std::sqrt(squares / 400 - mean * mean);
  CHECK(mean == Approx(0.5).margin(0.05));
  CHECK(spread > 0.08);
  CHECK(largest_step < 0.02);  // a step of 1e-3 moves it little: no jumps
}

}  // namespace texture_kernel_test
