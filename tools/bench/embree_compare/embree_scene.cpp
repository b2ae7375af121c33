#include "embree_scene.hpp"

#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

namespace clrt::compare {
namespace {

// The sphere radius when the transform's upper 3x3 is a rotation (or mirror) times a uniform
// scale, which Embree's sphere primitive can take; 0 otherwise.
double uniform_scale_radius(const Mat4& m) {
  const Vec3 column[3] = {{m.m[0][0], m.m[1][0], m.m[2][0]},
                          {m.m[0][1], m.m[1][1], m.m[2][1]},
                          {m.m[0][2], m.m[1][2], m.m[2][2]}};
  const double s2 = dot(column[0], column[0]);
  constexpr double kTolerance = 1e-6;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      const double expected = i == j ? s2 : 0;
      if (std::abs(dot(column[i], column[j]) - expected) > kTolerance * s2) return 0;
    }
  return std::sqrt(s2);
}

RTCGeometry triangle_geometry(RTCDevice device, const std::vector<Vec3>& positions,
                              const std::vector<std::uint32_t>& corners) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // rtcSetNewGeometryBuffer pads the buffers as Embree's SIMD loads need.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), corners.size() / 3));
  if (!vertices || !indices) return geometry;  // the error callback has the reason
  for (std::size_t k = 0; k < positions.size(); ++k) {
    vertices[3 * k] = static_cast<float>(positions[k].x);
    vertices[3 * k + 1] = static_cast<float>(positions[k].y);
    vertices[3 * k + 2] = static_cast<float>(positions[k].z);
  }
  for (std::size_t k = 0; k < corners.size(); ++k) indices[k] = corners[k];
  rtcCommitGeometry(geometry);
  return geometry;
}

void attach(RTCScene scene, RTCGeometry geometry) {
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
}

void record_error(void* user, RTCError, const char* message) {
  *static_cast<std::string*>(user) = message ? message : "unknown error";
}

RTCRay embree_ray(const HostRay& r, float tfar) {
  RTCRay ray{};
  ray.org_x = r.origin[0];
  ray.org_y = r.origin[1];
  ray.org_z = r.origin[2];
  ray.tnear = kTmin;
  ray.dir_x = r.dir[0];
  ray.dir_y = r.dir[1];
  ray.dir_z = r.dir[2];
  ray.tfar = tfar;
  ray.mask = ~0u;
  return ray;
}

}  // namespace

std::string unsupported_shapes(const Scene& scene) {
  std::map<std::string, int> counts;
  for (const InstanceSpec& i : scene.instances) {
    switch (i.shape) {
      case ShapeKind::Cube:
        ++counts["cubes"];
        break;
      case ShapeKind::Cylinder:
        ++counts["cylinders"];
        break;
      case ShapeKind::Cone:
        ++counts["cones"];
        break;
      case ShapeKind::Sphere:
        if (uniform_scale_radius(i.transform) == 0) ++counts["non-uniformly scaled spheres"];
        break;
      default:
        break;
    }
  }
  std::string list;
  for (const auto& [what, n] : counts)
    list += (list.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  return list;
}

EmbreeScene::EmbreeScene(const Scene& scene, int threads, RTCBuildQuality quality,
                         RTCSceneFlags flags)
    : device_(rtcNewDevice(("threads=" + std::to_string(threads)).c_str())),
      quality_(quality),
      flags_(flags) {
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(device_, record_error, &error_);
  const auto start = std::chrono::steady_clock::now();
  top_ = new_scene();
  mesh_scenes_.assign(scene.meshes.size(), nullptr);
  add_meshes(scene);
  add_spheres(scene);
  add_loose_triangles(scene);
  rtcCommitScene(top_);
  build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  check();
}

EmbreeScene::~EmbreeScene() {
  for (RTCScene s : mesh_scenes_)
    if (s) rtcReleaseScene(s);
  rtcReleaseScene(top_);
  rtcReleaseDevice(device_);
}

void EmbreeScene::check() const {
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("Embree: " + error_);
}

RTCScene EmbreeScene::new_scene() const {
  RTCScene scene = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene, quality_);
  rtcSetSceneFlags(scene, flags_);
  return scene;
}

RTCScene EmbreeScene::mesh_scene(const MeshData& mesh) {
  RTCScene scene = new_scene();
  attach(scene, triangle_geometry(device_, mesh.positions, mesh.corners));
  rtcCommitScene(scene);
  check();
  return scene;
}

// Mesh instances become Embree instances of one shared scene per mesh file; planes are kept
// for the host-side test.
void EmbreeScene::add_meshes(const Scene& scene) {
  for (const InstanceSpec& i : scene.instances) {
    if (i.shape == ShapeKind::Plane) {
      const Mat4 inverse = i.transform.inverse();
      const double* row = inverse.m[1];
      planes_.push_back({{static_cast<float>(row[0]), static_cast<float>(row[1]),
                          static_cast<float>(row[2]), static_cast<float>(row[3])}});
    }
    if (i.shape != ShapeKind::Mesh) continue;
    RTCScene& model = mesh_scenes_.at(static_cast<std::size_t>(i.mesh));
    if (!model) model = mesh_scene(scene.meshes[static_cast<std::size_t>(i.mesh)]);
    RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, model);
    float rows[12];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) rows[4 * r + c] = static_cast<float>(i.transform.m[r][c]);
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
    rtcCommitGeometry(instance);
    attach(top_, instance);
  }
}

void EmbreeScene::add_spheres(const Scene& scene) {
  std::vector<float> points;  // x y z radius
  for (const InstanceSpec& i : scene.instances) {
    if (i.shape != ShapeKind::Sphere) continue;
    const Vec3 centre = i.transform.transform_point({0, 0, 0});
    points.insert(points.end(), {static_cast<float>(centre.x), static_cast<float>(centre.y),
                                 static_cast<float>(centre.z),
                                 static_cast<float>(uniform_scale_radius(i.transform))});
  }
  if (points.empty()) return;
  RTCGeometry spheres = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* buffer = static_cast<float*>(rtcSetNewGeometryBuffer(
      spheres, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), points.size() / 4));
  if (buffer) std::copy(points.begin(), points.end(), buffer);
  rtcCommitGeometry(spheres);
  attach(top_, spheres);
}

void EmbreeScene::add_loose_triangles(const Scene& scene) {
  if (scene.triangles.empty()) return;
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> corners;
  for (const TriangleSpec& t : scene.triangles)
    for (const Vec3& v : {t.v0, t.v1, t.v2}) {
      corners.push_back(static_cast<std::uint32_t>(positions.size()));
      positions.push_back(v);
    }
  attach(top_, triangle_geometry(device_, positions, corners));
}

Bounds EmbreeScene::bounds() const {
  RTCBounds b;
  rtcGetSceneBounds(top_, &b);
  if (!(b.lower_x <= b.upper_x))
    throw std::runtime_error("the scene has nothing but planes: no bounds for random rays");
  return {{b.lower_x, b.lower_y, b.lower_z}, {b.upper_x, b.upper_y, b.upper_z}};
}

// As clrt's plane test: object-space height o'y + t d'y = 0, hits with kTmin < t < tmax.
float EmbreeScene::nearest_plane(const HostRay& ray, float tmax) const {
  float best = tmax;
  for (const Plane& p : planes_) {
    const float oy =
        p.row[0] * ray.origin[0] + p.row[1] * ray.origin[1] + p.row[2] * ray.origin[2] + p.row[3];
    const float dy = p.row[0] * ray.dir[0] + p.row[1] * ray.dir[1] + p.row[2] * ray.dir[2];
    if (dy == 0.0f) continue;
    const float t = -oy / dy;
    if (t > kTmin && t < best) best = t;
  }
  return best;
}

float EmbreeScene::closest_t(const HostRay& ray) const {
  RTCRayHit hit{};
  hit.ray = embree_ray(ray, nearest_plane(ray, INFINITY));
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(top_, &context, &hit);
  // tfar only shrinks on a hit: it is the plane's t, or INFINITY, when Embree found nothing.
  return hit.ray.tfar;
}

bool EmbreeScene::occluded(const HostRay& ray) const {
  if (nearest_plane(ray, ray.tmax) < ray.tmax) return true;
  RTCRay query = embree_ray(ray, ray.tmax);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(top_, &context, &query);
  return query.tfar < 0;  // Embree sets tfar to -inf on a hit
}

}  // namespace clrt::compare
