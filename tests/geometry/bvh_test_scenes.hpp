// Scenes and rays for the BVH tests, filled into clrt::Scene directly (no loader involved).
#pragma once

#include <random>
#include <vector>

#include "scene/scene.hpp"

namespace clrt::bvhtest {


// A random rotation, non-uniform scale (0.3 to 2 per axis) and translation within +-`spread`.
Mat4 random_transform(std::mt19937& rng, double spread);

// A random rotation, uniform scale in [min_scale, max_scale] and translation within +-`spread`.
Mat4 random_similarity(std::mt19937& rng, double spread, double min_scale, double max_scale);

// A closed mesh: a sphere-like ball of `rings` x `segments` quads split into triangles, with
// per-vertex normals when `with_normals`.
MeshData ball_mesh(int rings, int segments, bool with_normals);

// The triangle (0,0,0) (1,0,0) (0,1,0) with the given vertex normals, one per corner.
MeshData triangle_mesh_with_normals(const Vec3& n0, const Vec3& n1, const Vec3& n2);

// `count` spheres, cubes, cylinders and cones under random transforms, one plane, `triangles`
// random loose triangles with cycling materials, and two instances of a small ball mesh.
Scene random_scene(std::mt19937& rng, int count, int triangles);

// `count` spheres under similarities (which the BVH tests in world space, in packets) with
// radii over three orders of magnitude, so that many overlap, a few of them within others; a
// few ellipsoids; one instance of a small ball mesh.
Scene sphere_scene(std::mt19937& rng, int count);

struct TestRay {
  Vec3 o, d;
  double tmin = 0, tmax = 1e30;
};

// Rays of every kind a renderer sends: from random points in random directions (many start
// inside BVH boxes), exactly axis-parallel ones, ones aimed at points inside objects, ones
// starting at object centres, and ones with finite tmax; directions are not all unit.
std::vector<TestRay> random_rays(std::mt19937& rng, const Scene& scene, int count);

}  // namespace clrt::bvhtest
