// An instanced mesh renders as the same triangles written out one by one.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "render_support.hpp"
#include "scene/scene.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const char* const kHeader =
    "eye 3 2.5 6\nlookat 0 0 0\nresolution 120 90\nbackground 0.1 0.1 0.2\n"
    "light 0.2 0.2 0.2 ambient\nlight 0.8 0.8 0.8 point 4 6 5\n"
    "material 0.8 0.5 0.2 0.3 0.7 0.5 30 0.2 0 1\n";

// The scene's one mesh as `triangle` commands (object space), each after `transform`.
std::string triangles_of(const Scene& scene, const std::string& transform) {
  REQUIRE(scene.meshes.size() == 1);
  const MeshData& mesh = scene.meshes[0];
  std::ostringstream out;
  out.precision(9);
  for (std::size_t t = 0; t + 2 < mesh.corners.size(); t += 3) {
    out << transform << "triangle";
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3& v = mesh.positions[mesh.corners[t + k]];
      out << ' ' << v.x << ' ' << v.y << ' ' << v.z;
    }
    out << "\nreset\n";
  }
  return out.str();
}

// The largest difference of any channel of any pixel, in 8-bit steps.
int max_difference(const FloatImage& a, const FloatImage& b) {
  const Rgba8Image qa = quantize(a), qb = quantize(b);
  int worst = 0;
  for (std::size_t i = 0; i < qa.frames[0].size(); ++i)
    worst = std::max(worst, std::abs(int(qa.frames[0][i]) - int(qb.frames[0][i])));
  return worst;
}

struct Pair {
  FloatImage instanced, loose;
};

Pair render_both(const std::string& transform) {
  ScratchDir dir;
  const std::string obj = std::string(CLRT_SOURCE_DIR) + "/scenes/meshes/pyramid.obj";
  const std::string instanced =
      dir.write("instanced.ray", std::string(kHeader) + transform + "mesh \"" + obj + "\"\n");
  const std::string loose =
      dir.write("loose.ray", kHeader + triangles_of(load_scene(instanced), transform));
  return {render_file(instanced), render_file(loose)};
}

}  // namespace

TEST_CASE("an instanced mesh renders bit for bit as its triangles written out", "[render][mesh]") {
  const Pair p = render_both("");
  REQUIRE(p.instanced.rgb.size() == p.loose.rgb.size());
  // The pyramid covers part of the picture: not every pixel is the background's blue.
  std::size_t covered = 0;
  for (std::size_t i = 2; i < p.loose.rgb.size(); i += 3) covered += p.loose.rgb[i] != 0.2f;
  CHECK(covered > 500);
  CHECK(p.instanced.rgb == p.loose.rgb);
}

TEST_CASE("under a transform the two agree to the last 8-bit step", "[render][mesh]") {
  const Pair p = render_both("rotate 30 1 2 0.5\nscale 1.2 0.8 1\ntranslate 0.3 -0.2 0.1\n");
  CHECK(max_difference(p.instanced, p.loose) <= 1);
}
