// An independent Whitted ray tracer in double on the host, written from the contract, for
// scenes of spheres, planes y = c, point and directional lights, without refraction. The render
// tests describe a .ray scene to it by hand (their own reading of the file) and compare pixels.
#pragma once

#include <array>
#include <vector>

#include "math/vec3.hpp"
#include "reference_camera.hpp"

namespace clrt::test {

struct RefMaterial {
  Vec3 color;
  double ka, kd, ks, shininess, kr;
};

struct RefSphere {
  Vec3 centre;
  double radius;
  int material;
};

struct RefPlane {  // y = height, front face +y
  double height;
  int material;
};

struct RefLight {
  Vec3 color;
  Vec3 position;       // point light
  Vec3 travel;         // directional light: direction of travel
  bool directional = false;
};

enum class RefMode { Trace, Cast };

struct RefScene {
  RefScene(const ContractCamera& camera_, const Vec3& background_, const Vec3& ambient_)
      : camera(camera_), background(background_), ambient(ambient_) {}

  ContractCamera camera;
  Vec3 background, ambient;
  int max_depth = 5;
  std::vector<RefMaterial> materials;
  std::vector<RefSphere> spheres;
  std::vector<RefPlane> planes;
  std::vector<RefLight> lights;
};

// What a primary ray sees first, for choosing pixels: nothing, a surface that every light
// facing it reaches, or a surface that at least one light facing it cannot reach.
enum class Visibility { Background, Lit, Shadowed };

struct RefHit {
  double t = 0;
  Vec3 normal;  // unit, as the surface defines it
  int material = -1;
  int object = -1;  // spheres first, then planes; -1 on a miss
};

RefHit closest_hit(const RefScene& scene, const Vec3& origin, const Vec3& dir);

// The colour of a ray (unclamped) and of image point (x, y).
Vec3 radiance(const RefScene& scene, const Vec3& origin, const Vec3& dir, int depth, RefMode mode);
Vec3 image_colour(const RefScene& scene, double x, double y, RefMode mode);

Visibility visibility(const RefScene& scene, double x, double y);

// The contract's quantisation: clamp to [0, 1], times 255, round to nearest.
std::array<int, 3> quantise(const Vec3& colour);

// Every channel within 1 of the other's: the tolerance of a float render against the reference.
bool within_one(const std::array<int, 3>& a, const std::array<int, 3>& b);

// Pixel (i, j)'s centre and four points 0.02 pixels around it quantise alike and see alike:
// a pixel that no rounding in a float renderer can push over an edge.
bool robust_pixel(const RefScene& scene, int i, int j, RefMode mode);

}  // namespace clrt::test
