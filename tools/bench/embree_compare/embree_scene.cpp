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

unsigned attach(RTCScene scene, RTCGeometry geometry) {
  const unsigned id = rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  return id;
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
    if (i.motion >= 0) ++counts["moving objects"];  // Embree would trace one pose of them
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
      flags_(flags),
      scene_(scene) {
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
  normal_matrix_.resize(scene.instances.size());
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const InstanceSpec& i = scene.instances[k];
    if (i.shape != ShapeKind::Plane && i.shape != ShapeKind::Mesh) continue;
    const Mat4 inverse = i.transform.inverse();
    normal_matrix_[k] = inverse.transposed();
    if (i.shape == ShapeKind::Plane) {
      const double* row = inverse.m[1];
      planes_.push_back({{static_cast<float>(row[0]), static_cast<float>(row[1]),
                          static_cast<float>(row[2]), static_cast<float>(row[3])},
                         static_cast<int>(k)});
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
    const unsigned id = attach(top_, instance);
    if (top_instance_.size() <= id) top_instance_.resize(id + 1, -1);
    top_instance_[id] = static_cast<int>(k);
  }
}

void EmbreeScene::add_spheres(const Scene& scene) {
  std::vector<float> points;  // x y z radius
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const InstanceSpec& i = scene.instances[k];
    if (i.shape != ShapeKind::Sphere) continue;
    sphere_instance_.push_back(static_cast<int>(k));
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
  spheres_id_ = attach(top_, spheres);
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
  loose_id_ = attach(top_, triangle_geometry(device_, positions, corners));
}

Bounds EmbreeScene::bounds() const {
  RTCBounds b;
  rtcGetSceneBounds(top_, &b);
  if (!(b.lower_x <= b.upper_x))
    throw std::runtime_error("the scene has nothing but planes: no bounds for random rays");
  return {{b.lower_x, b.lower_y, b.lower_z}, {b.upper_x, b.upper_y, b.upper_z}};
}

// As clrt's plane test: object-space height o'y + t d'y = 0, hits with kTmin < t < tmax.
float EmbreeScene::nearest_plane(const HostRay& ray, float tmax, int* which) const {
  float best = tmax;
  if (which) *which = -1;
  for (const Plane& p : planes_) {
    const float oy =
        p.row[0] * ray.origin[0] + p.row[1] * ray.origin[1] + p.row[2] * ray.origin[2] + p.row[3];
    const float dy = p.row[0] * ray.dir[0] + p.row[1] * ray.dir[1] + p.row[2] * ray.dir[2];
    if (dy == 0.0f) continue;
    const float t = -oy / dy;
    if (t > kTmin && t < best) {
      best = t;
      if (which) *which = p.instance;
    }
  }
  return best;
}

RTCRayHit EmbreeScene::intersect(const HostRay& ray, int* plane) const {
  RTCRayHit hit{};
  hit.ray = embree_ray(ray, nearest_plane(ray, INFINITY, plane));
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(top_, &context, &hit);
  return hit;
}

float EmbreeScene::closest_t(const HostRay& ray) const {
  // tfar only shrinks on a hit: it is the plane's t, or INFINITY, when Embree found nothing.
  return intersect(ray, nullptr).ray.tfar;
}

// The triangle's own normal, and its vertex normals interpolated at (u, v) as clrt does (each
// corner's normal made unit first, the face normal where it cannot be), both in world space.
SurfaceHit EmbreeScene::mesh_hit(const RTCHit& hit, int instance) const {
  const InstanceSpec& spec = scene_.instances[static_cast<std::size_t>(instance)];
  const MeshData& mesh = scene_.meshes[static_cast<std::size_t>(spec.mesh)];
  const std::uint32_t* c = &mesh.corners[3 * std::size_t{hit.primID}];
  const Vec3 face = cross(mesh.positions[c[1]] - mesh.positions[c[0]], mesh.positions[c[2]] - mesh.positions[c[0]]);
  const Mat4& to_world = normal_matrix_[static_cast<std::size_t>(instance)];
  SurfaceHit out;
  out.material = mesh_triangle_material(spec, mesh, hit.primID);
  out.normal = unit_or_zero(to_world.transform_vector(face));
  out.shading_normal = out.normal;
  if (!mesh.normals.empty()) {
    const std::uint32_t* n = &mesh.corner_normals[3 * std::size_t{hit.primID}];
    const double w[3] = {1.0 - hit.u - hit.v, hit.u, hit.v};
    Vec3 sum;
    for (int k = 0; k < 3; ++k) {
      Vec3 corner = unit_or_zero(mesh.normals[n[k]]);
      if (corner == Vec3{}) corner = unit_or_zero(face);
      sum = sum + corner * w[k];
    }
    const Vec3 shading = unit_or_zero(to_world.transform_vector(sum));
    if (shading != Vec3{}) out.shading_normal = shading;
  }
  return out;
}

SurfaceHit EmbreeScene::closest_hit(const HostRay& ray) const {
  int plane = -1;
  const RTCRayHit rh = intersect(ray, &plane);
  SurfaceHit out;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID && plane < 0) return out;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    const std::size_t k = static_cast<std::size_t>(plane);
    out.normal = out.shading_normal = unit_or_zero(normal_matrix_[k].transform_vector({0, 1, 0}));
    out.material = scene_.instances[k].material;
  } else if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
    out = mesh_hit(rh.hit, top_instance_.at(rh.hit.instID[0]));
  } else if (rh.hit.geomID == spheres_id_) {
    const InstanceSpec& spec = scene_.instances[static_cast<std::size_t>(sphere_instance_.at(rh.hit.primID))];
    out.normal = out.shading_normal =
        unit_or_zero(ray.origin_vec() + ray.dir_vec() * rh.ray.tfar - spec.transform.transform_point({0, 0, 0}));
    out.material = spec.material;
  } else if (rh.hit.geomID == loose_id_) {
    const TriangleSpec& tri = scene_.triangles.at(rh.hit.primID);
    out.normal = out.shading_normal = unit_or_zero(cross(tri.v1 - tri.v0, tri.v2 - tri.v0));
    out.material = tri.material;
  } else {
    throw std::logic_error("Embree hit a geometry this scene did not attach");
  }
  out.t = rh.ray.tfar;
  return out;
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
