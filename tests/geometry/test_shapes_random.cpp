// Canonical objects on the device against the independent host reference, for hundreds of
// random rays per object and transform: general rays, rays starting inside, world-axis-parallel
// rays (exact zeros in object space under translate and scale) and rays grazing a silhouette,
// edge, rim or apex; with random tmin and tmax.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "test_shapes_kernel.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

constexpr int kRaysPerTransform = 400;

// Identity, each kind of transform alone, a composite, and a mirroring one.
std::vector<Mat4> transforms() {
  return {Mat4::identity(),
          Mat4::translate({1.5, -0.7, 2}),
          Mat4::scale({2, 0.5, 1.3}),
          Mat4::rotate(37, {1, 2, -0.5}),
          Mat4::translate({-1, 2, 0.5}) * Mat4::rotate(-110, {0.3, -1, 2}) *
              Mat4::scale({0.7, 1.8, 1.1}),
          Mat4::rotate(25, {1, 1, 0}) * Mat4::scale({-1.2, 0.8, 1})};
}

class RayMaker {
 public:
  explicit RayMaker(unsigned seed) : rng_(seed) {}

  // Ray number `i` for `shape`: its family is chosen by i.
  WorldRay next(const PlacedShape& shape, int i) {
    const Mat4& m = shape.transform;
    WorldRay ray;
    const int family = i % 20;
    if (family < 10) {
      ray.origin = m.transform_point(in_box(4));
      ray.dir = m.transform_point(in_box(1.3)) - ray.origin;
    } else if (family < 13) {
      ray.origin = m.transform_point(in_box(0.6));
      ray.dir = direction();
    } else if (family < 16) {
      ray.origin = m.transform_point(in_box(1.5));
      const int axis = static_cast<int>(uniform(0, 3)) % 3;
      const double sign = uniform(0, 1) < 0.5 ? -1 : 1;
      ray.dir = {axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0};
    } else {
      const Vec3 target = boundary_point(shape);
      const Vec3 d = grazing_direction(shape, target);
      ray.origin = m.transform_point(target - uniform(2, 4) * d);
      ray.dir = m.transform_vector(d);
    }
    ray.origin = round_to_float(ray.origin);
    ray.dir = round_to_float(ray.dir * (uniform(0.3, 2) / length(ray.dir)));
    ray.tmin = uniform(0, 1) < 0.7 ? 1e-4 : static_cast<float>(uniform(0, 4));
    ray.tmax = uniform(0, 1) < 0.5 ? ray.tmax : static_cast<float>(uniform(0.5, 12));
    return ray;
  }

 private:
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  Vec3 in_box(double h) { return {uniform(-h, h), uniform(-h, h), uniform(-h, h)}; }

  Vec3 direction() {
    std::normal_distribution<double> normal;
    return normalize(Vec3{normal(rng_), normal(rng_), normal(rng_)});
  }

  // An object-space point where hit and miss are decided by a hair: on the sphere, on the
  // plane, on a cube edge, on a rim or at a cone's apex.
  Vec3 boundary_point(const PlacedShape& shape) {
    const double angle = uniform(0, 2 * M_PI), side = uniform(0, 1) < 0.5 ? -1 : 1;
    switch (shape.shape) {
      case CLRT_SHAPE_SPHERE: return direction();
      case CLRT_SHAPE_PLANE: return {uniform(-3, 3), 0, uniform(-3, 3)};
      case CLRT_SHAPE_CUBE: {
        const double a = uniform(0, 1) < 0.5 ? -1 : 1, b = uniform(-1, 1);
        const int axis = static_cast<int>(uniform(0, 3)) % 3;
        return axis == 0 ? Vec3{b, a, side} : (axis == 1 ? Vec3{side, b, a} : Vec3{a, side, b});
      }
      default: {
        const double r = shape.shape == CLRT_SHAPE_CYLINDER ? 1 : (side < 0 ? shape.cone_r0 : shape.cone_r1);
        return {r * std::cos(angle), side, r * std::sin(angle)};
      }
    }
  }

  // Tangent to the sphere, nearly parallel to the plane, anything through edges and rims.
  Vec3 grazing_direction(const PlacedShape& shape, const Vec3& target) {
    if (shape.shape == CLRT_SHAPE_SPHERE) return normalize(cross(target, direction()));
    if (shape.shape == CLRT_SHAPE_PLANE) {
      const Vec3 d = direction();
      return normalize(Vec3{d.x, uniform(-1e-3, 1e-3), d.z});
    }
    return direction();
  }

  std::mt19937 rng_;
};

void check_against_reference(dev::u32 shape, double r0 = 1, double r1 = 0) {
  RayMaker maker(1000 + shape);
  std::vector<PlacedShape> shapes;
  std::vector<WorldRay> rays;
  for (const Mat4& m : transforms()) {
    for (int i = 0; i < kRaysPerTransform; ++i) {
      shapes.push_back({shape, r0, r1, m});
      rays.push_back(maker.next(shapes.back(), i));
    }
  }
  const int compared = compare_with_reference(shapes, rays);
  INFO(compared << " of " << rays.size() << " rays were well-conditioned enough to compare");
  CHECK(compared >= static_cast<int>(0.75 * rays.size()));
}

}  // namespace

TEST_CASE("sphere agrees with the host reference on random rays", "[shapes][random]") {
  check_against_reference(CLRT_SHAPE_SPHERE);
}

TEST_CASE("plane agrees with the host reference on random rays", "[shapes][random]") {
  check_against_reference(CLRT_SHAPE_PLANE);
}

TEST_CASE("cube agrees with the host reference on random rays", "[shapes][random]") {
  check_against_reference(CLRT_SHAPE_CUBE);
}

TEST_CASE("cylinder agrees with the host reference on random rays", "[shapes][random]") {
  check_against_reference(CLRT_SHAPE_CYLINDER);
}

TEST_CASE("cones agree with the host reference on random rays", "[shapes][random]") {
  SECTION("apex at the top") { check_against_reference(CLRT_SHAPE_CONE, 1, 0); }
  SECTION("frustum") { check_against_reference(CLRT_SHAPE_CONE, 1, 0.4); }
  SECTION("apex at the bottom") { check_against_reference(CLRT_SHAPE_CONE, 0, 1); }
  SECTION("widening frustum") { check_against_reference(CLRT_SHAPE_CONE, 0.5, 1.5); }
}
