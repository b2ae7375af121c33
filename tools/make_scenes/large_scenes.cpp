#include "large_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "obj_writer.hpp"
#include "random_stream.hpp"
#include "ray_writer.hpp"
#include "torus_knot.hpp"

namespace clrt::scenes {
namespace {

constexpr double kPi = 3.141592653589793;

const std::vector<Look> kPalette = {
    {{0.9, 0.75, 0.45}, 0.1, 0.8, 0.5, 40, 0.2, 0},
    {{0.35, 0.55, 0.95}, 0.1, 0.8, 0.3, 20, 0, 0},
    {{0.95, 0.4, 0.55}, 0.1, 0.8, 0.3, 20, 0, 0},
    {{0.6, 0.9, 0.6}, 0.1, 0.7, 0.6, 80, 0.3, 0},
};
const Look kFloor{{0.55, 0.55, 0.6}, 0.1, 0.7, 0.1, 10, 0.15, 0};
const Vec3 kBackground{0.05, 0.06, 0.1};

struct Ball {
  Vec3 centre;
  double radius;
  int look;
};

// A point of the unit ball, by rejection.
Vec3 point_in_ball(RandomStream& random) {
  for (;;) {
    const Vec3 p{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)};
    if (dot(p, p) <= 1) return p;
  }
}

// A fifth of the spheres in a flattened central bulge, the rest in three spiral arms whose
// disc thins out towards the rim; the arm a sphere belongs to picks its colour.
Ball galaxy_ball(RandomStream& random) {
  const double radius = random.uniform(0.03, 0.07);
  if (random.uniform() < 0.2) {
    const Vec3 p = point_in_ball(random);
    return {{2.5 * p.x, 2.5 + 1.0 * p.y, 2.5 * p.z}, radius, 0};
  }
  const int arm = static_cast<int>(random.uniform() * 3);
  const double d = 1.5 + 9.0 * std::sqrt(random.uniform());
  const double angle = arm * 2 * kPi / 3 + 0.45 * d + random.uniform(-0.35, 0.35);
  const double thickness = 0.5 * (1 - d / 12);
  return {{d * std::cos(angle) + random.uniform(-0.3, 0.3), 2.5 + thickness * random.uniform(-1, 1),
           d * std::sin(angle) + random.uniform(-0.3, 0.3)},
          radius,
          1 + arm};
}

void two_lights(RayWriter& out, double distance) {
  out.point_light({0.8, 0.8, 0.75}, Vec3{-0.5, 1.0, -0.6} * distance);
  out.point_light({0.35, 0.35, 0.45}, Vec3{0.8, 0.5, 0.3} * distance);
}

// Instances written one palette colour at a time, so the scene has one material per colour.
void write_instances(RayWriter& out, const std::string& mesh,
                     const std::vector<Placement>& placements) {
  for (int look = 0; look < static_cast<int>(kPalette.size()); ++look) {
    out.material(kPalette[look]);
    for (const Placement& p : placements)
      if (p.look == look) out.mesh_instance(mesh, p);
  }
}

class SceneSet {
 public:
  SceneSet(const std::string& folder, double scale) : folder_(folder), scale_(scale) {
    std::filesystem::create_directories(folder_);
  }

  void galaxy() {
    const long long count = scaled_count(100000, scale_);
    RandomStream random(1);
    std::vector<Ball> balls;
    for (long long k = 0; k < count; ++k) balls.push_back(galaxy_ball(random));
    RayWriter out = scene("spheres-100k.ray",
                          std::to_string(count) + " spheres in a spiral galaxy over a floor plane");
    out.camera({{0, 12, -20}, {0, 1.5, 0}, 60, 800, 600}, kBackground);
    two_lights(out, 25);
    out.material(kFloor);
    out.floor_plane();
    for (int look = 0; look < static_cast<int>(kPalette.size()); ++look) {
      out.material(kPalette[look]);
      for (const Ball& b : balls)
        if (b.look == look) out.sphere(b.centre, b.radius);
    }
    out.close();
  }

  // A 10 x 10 grid of the million-triangle knot on a floor, each turned and tilted.
  void knot_grid() {
    const std::string mesh = knot("1m", 1000000);
    const long long count = scaled_count(100, scale_);
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    const int rows = static_cast<int>((count + columns - 1) / columns);
    constexpr double kSpacing = 7.5;
    RandomStream random(2);
    std::vector<Placement> placements;
    for (long long k = 0; k < count; ++k) {
      const Vec3 cell{(k % columns - (columns - 1) / 2.0) * kSpacing, 2.4,
                      (k / columns - (rows - 1) / 2.0) * kSpacing};
      placements.push_back({1, random.uniform(-20, 20), random.uniform(0, 360), cell,
                            static_cast<int>(k % static_cast<long long>(kPalette.size()))});
    }
    const double extent = columns * kSpacing / 2;
    RayWriter out =
        scene("mesh-1m-x100.ray", std::to_string(count) + " instances of " + mesh + " in a grid");
    out.camera({{0, 0.9 * extent + 4, -1.5 * extent - 6}, {0, 0, 0}, 60, 800, 600}, kBackground);
    two_lights(out, 3 * extent);
    out.material(kFloor);
    out.floor_plane();
    write_instances(out, mesh, placements);
    out.close();
  }

  // One knot per file, 1k to 1M triangles, seen whole.
  void triangle_series() {
    for (const auto& [label, triangles] : kTriangleSeries) {
      const std::string mesh = knot(label, triangles);
      RayWriter out = scene("tri-" + label + ".ray", "one instance of " + mesh);
      out.camera({{0, 5, -9}, {0, 0, 0}, 50, 512, 512}, kBackground);
      two_lights(out, 20);
      write_instances(out, mesh, {Placement{}});
      out.close();
    }
  }

  // 10 to 100k instances of the 1k-triangle knot, randomly turned and scaled, in a jittered
  // cubic grid of constant density: the scene grows with the count.
  void instance_series() {
    const std::string mesh = knot("1k", 1000);
    for (const auto& [label, full_size] : kInstanceSeries) {
      const long long count = scaled_count(full_size, scale_);
      const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(count)) - 1e-9));
      constexpr double kSpacing = 7;
      RandomStream random(3);
      std::vector<Placement> placements;
      for (long long k = 0; k < count; ++k) {
        const auto cell = [&](long long index) {
          return (index % side - (side - 1) / 2.0) * kSpacing + random.uniform(-1, 1);
        };
        const Vec3 position{cell(k), cell(k / side), cell(k / side / side)};
        placements.push_back({random.uniform(0.6, 1.0), random.uniform(0, 180),
                              random.uniform(0, 360), position,
                              static_cast<int>(k % static_cast<long long>(kPalette.size()))});
      }
      const double extent = side * kSpacing / 2;
      RayWriter out = scene("inst-" + label + ".ray",
                            std::to_string(count) + " instances of " + mesh + " in a cube");
      out.camera({{0.8 * extent, 0.9 * extent, -2.2 * extent - 5}, {0, 0, 0}, 55, 512, 512},
                 kBackground);
      two_lights(out, 4 * extent);
      write_instances(out, mesh, placements);
      out.close();
    }
  }

  const std::vector<std::string>& files() const { return files_; }

 private:
  inline static const std::vector<std::pair<std::string, long long>> kTriangleSeries = {
      {"1k", 1000}, {"10k", 10000}, {"100k", 100000}, {"1m", 1000000}};
  inline static const std::vector<std::pair<std::string, long long>> kInstanceSeries = {
      {"10", 10}, {"100", 100}, {"1k", 1000}, {"10k", 10000}, {"100k", 100000}};

  RayWriter scene(const std::string& name, const std::string& description) {
    files_.push_back((folder_ / name).string());
    return RayWriter(files_.back(), description);
  }

  // knot-LABEL.obj with about `triangles` (scaled) triangles, written once per run; returns
  // its file name.
  std::string knot(const std::string& label, long long triangles) {
    const std::string name = "knot-" + label + ".obj";
    if (!knots_.insert(name).second) return name;
    const KnotGrid grid = knot_grid_for(scaled_count(triangles, scale_));
    files_.push_back((folder_ / name).string());
    write_obj(files_.back(), torus_knot(grid));
    return name;
  }

  std::filesystem::path folder_;
  double scale_;
  std::vector<std::string> files_;
  std::set<std::string> knots_;
};

}  // namespace

long long scaled_count(long long full_size, double scale) {
  return std::max(1LL, std::llround(static_cast<double>(full_size) * scale));
}

std::vector<std::string> write_large_scenes(const std::string& folder, double scale) {
  SceneSet set(folder, scale);
  set.galaxy();
  set.knot_grid();
  set.triangle_series();
  set.instance_series();
  return set.files();
}

}  // namespace clrt::scenes
