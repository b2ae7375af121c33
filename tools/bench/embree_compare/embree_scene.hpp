// The scene's geometry as a two-level Embree 3 scene: one bottom-level scene per mesh file,
// placed by Embree instances; spheres as RTC_GEOMETRY_TYPE_SPHERE_POINT; loose triangles in
// world space. Planes are unbounded, so, as in clrt, they are tested outside the BVH.
#pragma once

#include <embree3/rtcore.h>

#include <string>
#include <vector>

#include "host_rays.hpp"
#include "scene/scene.hpp"

namespace clrt::compare {

// What this comparison cannot give Embree (cubes, cylinders, cones, spheres under a
// transform that is not rotation + uniform scale + translation, objects that move), e.g. "4200
// cylinders";
// empty when everything can be compared.
std::string unsupported_shapes(const Scene& scene);

// What shading needs of a closest hit, worked out on the host from Embree's hit record.
struct SurfaceHit {
  float t = INFINITY;   // INFINITY: nothing was hit
  Vec3 normal;          // geometric, world space, unit, outward as the surface defines it
  Vec3 shading_normal;  // world space, unit: the interpolated vertex normal, else `normal`
  int material = 0;     // into Scene::materials
};

class EmbreeScene {
 public:
  // `threads` builds the BVHs, with `quality` and `flags` on every level; the scene must have no
  // unsupported_shapes() and must outlive this. Throws std::runtime_error with Embree's message
  // when Embree fails.
  EmbreeScene(const Scene& scene, int threads, RTCBuildQuality quality, RTCSceneFlags flags);
  EmbreeScene(Scene&& scene, int threads, RTCBuildQuality quality, RTCSceneFlags flags) = delete;
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  double build_seconds() const { return build_seconds_; }
  // The box of everything but the planes.
  Bounds bounds() const;

  // rtcIntersect1: the closest t in (kTmin, infinity), INFINITY on a miss.
  float closest_t(const HostRay& ray) const;
  // rtcIntersect1, with the hit's normals and material.
  SurfaceHit closest_hit(const HostRay& ray) const;
  // rtcOccluded1: whether anything lies in [kTmin, ray.tmax).
  bool occluded(const HostRay& ray) const;

 private:
  // Row 1 of the plane's M^-1: the ray's object-space height is row . (o, 1).
  struct Plane {
    float row[4];
    int instance;  // into Scene::instances
  };
  // The t of the nearest plane in (kTmin, tmax), else tmax; *which is its index, or -1.
  float nearest_plane(const HostRay& ray, float tmax, int* which = nullptr) const;
  // The rtcIntersect1 record of `ray`, planes included (tfar) but not reported in it.
  RTCRayHit intersect(const HostRay& ray, int* plane) const;
  SurfaceHit mesh_hit(const RTCHit& hit, int instance) const;

  RTCScene new_scene() const;
  RTCScene mesh_scene(const MeshData& mesh);
  void add_meshes(const Scene& scene);
  void add_spheres(const Scene& scene);
  void add_loose_triangles(const Scene& scene);
  void check() const;

  RTCDevice device_;
  RTCScene top_;
  RTCBuildQuality quality_;
  RTCSceneFlags flags_;
  std::vector<RTCScene> mesh_scenes_;  // per Scene::meshes entry, null until instanced
  std::vector<Plane> planes_;
  const Scene& scene_;
  // What each geometry of the top-level scene is, by its geometry ID: a mesh instance (its
  // index into Scene::instances), the spheres, or the loose triangles.
  std::vector<int> top_instance_;
  unsigned spheres_id_ = RTC_INVALID_GEOMETRY_ID, loose_id_ = RTC_INVALID_GEOMETRY_ID;
  std::vector<int> sphere_instance_;  // by the sphere's primitive ID
  std::vector<Mat4> normal_matrix_;   // (M^-1)^T of each instance that is a mesh or a plane
  std::string error_;  // the last message of Embree's error callback
  double build_seconds_ = 0;
};

}  // namespace clrt::compare
