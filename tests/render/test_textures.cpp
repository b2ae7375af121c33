// Textures end to end: an OBJ with an MTL map_Kd PNG shows its image the right way up in every
// mode and integrator; every shape's (u, v) runs as docs/scene-format.md says; a textured kr
// switches the mirror; and a checkerboard to the horizon at 1 sample per pixel keeps the
// pattern's mean over every block of pixels (computed here from the contract's camera), where
// point sampling folds it into moire.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <string>

#include "reference_camera.hpp"
#include "render_support.hpp"
#include "scene/scene_image.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace textures_render_test {

using Rgb = std::array<float, 3>;

// 8x8 texels, a colour per quadrant: the top left red, the top right green, the bottom left
// blue, the bottom right yellow (as sRGB codes).
const std::array<std::array<std::uint8_t, 3>, 4> kQuadrants = {{{200, 30, 30}, {30, 180, 40}, {20, 40, 210}, {230, 210, 30}}};

void write_quadrants(const ScratchDir& dir, const std::string& name) {
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const auto& c = kQuadrants[static_cast<std::size_t>((y < 4 ? 0 : 2) + (x < 4 ? 0 : 1))];
      rgba.insert(rgba.end(), {c[0], c[1], c[2], 255});
    }
  write_image(dir.file(name), Rgba8Image(8, 8, {rgba}));
}

Rgb linear(std::size_t quadrant) {
  const auto& c = kQuadrants[quadrant];
  return {srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2])};
}

Rgb pixel(const FloatImage& image, int x, int y) {
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * image.width + x);
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

// The quadrant whose colour `got` is nearest in direction (the shading scales all channels).
std::size_t quadrant_of(const Rgb& got) {
  std::size_t best = 0;
  double best_cos = -1;
  for (std::size_t q = 0; q < 4; ++q) {
    const Rgb c = linear(q);
    const double dot = got[0] * c[0] + got[1] * c[1] + got[2] * c[2];
    const double cos = dot / std::sqrt((got[0] * got[0] + got[1] * got[1] + got[2] * got[2]) *
                                       (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
    if (cos > best_cos) {
      best_cos = cos;
      best = q;
    }
  }
  return best;
}

TEST_CASE("an OBJ's map_Kd shows the right way up, Kd times the texel, in every mode and integrator",
          "[render][texture][mtl]") {
  ScratchDir dir;
  write_quadrants(dir, "label.png");
  // A 2x2 quad facing +z, (u, v) from (0, 0) at its bottom left to (1, 1) at its top right.
  dir.write("label.obj", "mtllib label.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl label\nf 1/1 2/2 3/3 4/4\n");
  dir.write("label.mtl", "newmtl label\nKd 0.5 1 0.75\nKs 0 0 0\nillum 1\nmap_Kd label.png\n");
  // The quad fills 40 of the 64 pixels across: each texel covers 5x5 pixels, so level 0 is read,
  // and a quadrant's middle pixel reads its colour alone. The white background lights the quad
  // evenly in path mode (every path's bounce escapes into it), so a pixel is Kd x texel there;
  // ambient light gives 0.2 Kd x texel in the Whitted modes.
  const double distance = 1 / std::tan(M_PI * 45 / 360) / (40.0 / 64);
  const std::string scene = dir.write(
      "label.ray", "eye 0 0 " + std::to_string(distance) + "\nlookat 0 0 0\nfov 45\nresolution 64 64\n"
                   "background 1 1 1\nlight 1 1 1 ambient\nmesh label.obj\n");
  const Rgb kd = {0.5f, 1, 0.75f};
  for (RenderMode mode : {RenderMode::Cast, RenderMode::Trace, RenderMode::Path}) {
    FloatImage first;
    for (const char* integrator : {"wavefront", "megakernel"}) {
      INFO("mode " << static_cast<int>(mode) << ", " << integrator);
      const FloatImage image = render_file(scene, [&](RenderOptions& o) {
        o.mode = mode;
        o.integrator = integrator;
      });
      const float share = mode == RenderMode::Path ? 1.0f : 0.2f;
      const int left = 22, right = 41, top = 22, bottom = 41;  // the quadrants' middles
      const std::array<std::array<int, 2>, 4> at = {{{left, top}, {right, top}, {left, bottom}, {right, bottom}}};
      for (std::size_t q = 0; q < 4; ++q) {
        const Rgb got = pixel(image, at[q][0], at[q][1]);
        const Rgb texel = linear(q);
        for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(share * kd[c] * texel[c]).epsilon(1e-5));
      }
      if (first.width == 0) first = image;
      else CHECK(same_bits(image, first));
    }
  }
}

TEST_CASE("every shape's (u, v) shows an image the right way up from outside", "[render][texture]") {
  ScratchDir dir;
  write_quadrants(dir, "q.png");
  // Seen from +z (the plane from +y, with -z up; each other face of the cube from outside, with
  // +y up or, for the top and bottom, -z and +z), each shape's middle is at (u, v) = (0.5, 0.5),
  // where the quadrants meet: up and left of it is the image's top left. The pixels read are 5
  // from the middle, a texel or more from the quadrants' border, where bilinear blending would
  // mix two colours.
  const std::string lit = "resolution 64 64\nfov 40\nbackground 0 0 0\nlight 1 1 1 ambient\n"
                          "material 1 1 1 1 0 0 1 0 0\ntexture color image q.png\n";
  const std::string front = "eye 0 0 6\nlookat 0 0 0\nup 0 1 0\n" + lit;
  const auto from = [&](const char* eye, const char* up) {
    return std::string("eye ") + eye + "\nlookat 0 0 0\nup " + up + "\n" + lit;
  };
  const std::array<std::pair<const char*, std::string>, 12> shapes = {{
      {"sphere", front + "sphere\n"},
      {"cube", front + "cube\n"},
      {"cube from +x", from("6 0 0", "0 1 0") + "cube\n"},
      {"cube from -x", from("-6 0 0", "0 1 0") + "cube\n"},
      {"cube from -z", from("0 0 -6", "0 1 0") + "cube\n"},
      {"cube from +y", from("0 6 0", "0 0 -1") + "cube\n"},
      {"cube from -y", from("0 -6 0", "0 0 1") + "cube\n"},
      {"cylinder's top cap", from("0 6 0", "0 0 -1") + "cylinder\n"},
      {"cylinder", front + "cylinder\n"},
      {"cone", front + "cone 1 0.6\n"},
      {"triangle", front + "triangle -1 -1 0 0 0  1 -1 0 1 0  1 1 0 1 1\ntriangle -1 -1 0 0 0  1 1 0 1 1  -1 1 0 0 1\n"},
      {"plane", "eye 0.5 6 -0.5\nlookat 0.5 0 -0.5\nup 0 0 -1\n" + lit + "plane\n"},
  }};
  for (const auto& [name, text] : shapes) {
    INFO(name);
    const FloatImage image = render_file(dir.write(std::string(name) + ".ray", text));
    CHECK(quadrant_of(pixel(image, 27, 27)) == 0);
    CHECK(quadrant_of(pixel(image, 37, 27)) == 1);
    CHECK(quadrant_of(pixel(image, 27, 37)) == 2);
    CHECK(quadrant_of(pixel(image, 37, 37)) == 3);
  }
}

TEST_CASE("a texture on kr makes a mirror of the white squares only", "[render][texture]") {
  // A mirror facing the camera reflects the background (0.25, 0.5, 1) where the checker is white
  // (kr 1) and shows its ambient colour where it is black (kr 0).
  ScratchDir dir;
  const std::string scene = dir.write(
      "mirror.ray", "eye 0 0 5\nlookat 0 0 0\nfov 40\nresolution 64 64\nbackground 0.25 0.5 1\n"
                    "light 1 1 1 ambient\nmaterial 1 0 0 0.5 0 0 1 1 0\ntexture kr checker 1 1 1 0 0 0\n"
                    "triangle -1 -1 0 0 0  1 -1 0 2 0  1 1 0 2 2\ntriangle -1 -1 0 0 0  1 1 0 2 2  -1 1 0 0 2\n");
  const FloatImage image = render_file(scene);
  // (u, v) runs 0 to 2 across the quad: its bottom-left square (floor sum 0) is white.
  const Rgb white_square = pixel(image, 24, 40), black_square = pixel(image, 40, 40);
  CHECK(white_square[0] == Approx(0.25f));
  CHECK(white_square[2] == Approx(1.0f));
  CHECK(black_square[0] == Approx(0.5f));
  CHECK(black_square[2] == Approx(0.0f).margin(1e-6));
}

TEST_CASE("a checkerboard to the horizon at 1 sample per pixel shows no moire", "[render][texture][filter]") {
  // The plane y = 0 under a camera 1 above it looking at the horizon, squares of 1/8, lit so
  // that a pixel is the pattern's value (ka 1, ambient 1). Moire is the pattern's squares
  // folded into a false pattern of larger scale, so it shows in the means of blocks of pixels,
  // which blurring leaves alone: each 8x4 block's mean must match the pattern's mean over the
  // block (by 16x16 points a pixel, from the contract's camera), as point sampling (one point a
  // pixel, the pixel's centre) does not.
  ScratchDir dir;
  const int width = 160, height = 64;
  const std::string scene = dir.write(
      "horizon.ray", "eye 0 1 0\nlookat 0 0.6 -10\nup 0 1 0\nfov 70\nresolution " + std::to_string(width) + " " +
                         std::to_string(height) + "\nbackground 0 0 0\nlight 1 1 1 ambient\n"
                         "material 1 1 1 1 0 0 1 0 0\ntexture color checker 1 1 1 0 0 0 scale 8 8\nplane\n");
  const ContractCamera camera({0, 1, 0}, {0, 0.6, -10}, {0, 1, 0}, 70, width, height);
  const FloatImage image = render_file(scene, [](RenderOptions& o) { o.samples = 1; });
  // The pattern at image point (x, y), or -1 where the ray misses the plane.
  const auto pattern = [&](double x, double y) {
    const Vec3 d = camera.direction(x, y);
    if (!(d.y < 0)) return -1.0;
    const Vec3 p = camera.eye + d * (camera.eye.y / -d.y);
    return (static_cast<long long>(std::floor(8 * p.x)) + static_cast<long long>(std::floor(-8 * p.z))) % 2 == 0 ? 1.0 : 0.0;
  };
  double filtered_error = 0, point_error = 0;
  int blocks = 0;
  for (int by = 0; by < height; by += 4)
    for (int bx = 0; bx < width; bx += 8) {
      // Blocks wholly on the plane and at least 4 away, where a pixel spans several squares.
      const Vec3 near = camera.direction(bx + 4, by + 4);
      if (!(near.y < 0) || camera.eye.y / -near.y < 4 || pattern(bx, by) < 0) continue;
      double reference = 0, rendered = 0, point = 0;
      for (int j = by; j < by + 4; ++j)
        for (int i = bx; i < bx + 8; ++i) {
          for (int b = 0; b < 16; ++b)
            for (int a = 0; a < 16; ++a) reference += pattern(i + (a + 0.5) / 16, j + (b + 0.5) / 16) / 256;
          rendered += pixel(image, i, j)[0];
          point += pattern(i + 0.5, j + 0.5);
        }
      filtered_error += std::pow((rendered - reference) / 32, 2);
      point_error += std::pow((point - reference) / 32, 2);
      ++blocks;
    }
  REQUIRE(blocks > 40);
  const double filtered_rms = std::sqrt(filtered_error / blocks), point_rms = std::sqrt(point_error / blocks);
  INFO("block means off by " << filtered_rms << " (rms), point sampled by " << point_rms << ", over " << blocks
                             << " blocks");
  CHECK(point_rms > 0.05);  // what moire looks like there: measured 0.070
  CHECK(filtered_rms < 0.02);  // measured 0.005
}

}  // namespace textures_render_test
