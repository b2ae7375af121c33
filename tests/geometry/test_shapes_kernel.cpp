#include "test_shapes_kernel.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cl_fixture.hpp"

namespace clrt::test {
namespace {

// rays: origin (w = tmin), direction (w = tmax); results: normal (w = t), (hit, u, v, 0).
const char* const kKernels = R"CL(
#include "geometry/instance.h"
#include "geometry/shapes.h"
#include "geometry/triangle.h"

__kernel void cast_canonical(__global const Instance* instances, __global const float4* rays,
                             uint count, __global float4* results) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  __global const Instance* inst = instances + i;
  const InstanceFrame frame = still_frame(inst);
  float3 o, d;
  ray_to_object(frame.to_object, rays[2 * i].xyz, rays[2 * i + 1].xyz, &o, &d);
  float t = rays[2 * i + 1].w;
  float3 n = (float3)(7.0f, 8.0f, 9.0f);
  const bool hit = intersect_canonical(inst->shape, inst->cone_r0, inst->cone_r1, o, d,
                                       rays[2 * i].w, &t, &n);
  results[2 * i] = (float4)(hit ? frame_normal_to_world(&frame, n) : n, t);
  results[2 * i + 1] = (float4)(hit ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
}

__kernel void cast_triangles(__global const Instance* instances, __global const Triangle* tris,
                             uint tri_count, uint stride, __global const float4* rays,
                             uint count, __global float4* results) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  __global const Instance* inst = instances + i;
  const InstanceFrame frame = still_frame(inst);
  float3 o, d;
  ray_to_object(frame.to_object, rays[2 * i].xyz, rays[2 * i + 1].xyz, &o, &d);
  float t = rays[2 * i + 1].w, u = -7.0f, v = -7.0f;
  float3 n = (float3)(7.0f, 8.0f, 9.0f);
  bool hit = false;
  for (uint k = 0; k < tri_count; ++k) {
    __global const Triangle* tri = tris + i * stride + k;
    if (intersect_triangle(tri->v0.xyz, tri->v1.xyz, tri->v2.xyz, o, d, rays[2 * i].w, &t, &u, &v)) {
      hit = true;
      n = frame_normal_to_world(&frame, triangle_normal(tri->v0.xyz, tri->v1.xyz, tri->v2.xyz));
    }
  }
  results[2 * i] = (float4)(n, t);
  results[2 * i + 1] = (float4)(hit ? 1.0f : 0.0f, u, v, 0.0f);
}
)CL";

dev::f4 to_f4(const Vec3& v, double w) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z),
          static_cast<float>(w)};
}

dev::Instance instance_of(const Mat4& m, dev::u32 shape, double r0, double r1) {
  const Mat4 inverse = m.inverse();
  dev::Instance instance{};
  for (int row = 0; row < 3; ++row)
    instance.world_to_object[row] = to_f4({inverse.m[row][0], inverse.m[row][1], inverse.m[row][2]},
                                          inverse.m[row][3]);
  instance.shape = shape;
  instance.cone_r0 = static_cast<float>(r0);
  instance.cone_r1 = static_cast<float>(r1);
  return instance;
}

struct CastCanonicalArgs {
  static constexpr const char* kName = "cast_canonical";
  Global<const dev::Instance> instances;
  Global<const dev::f4> rays;
  cl_uint count = 0;
  Global<dev::f4> results;
  CLRT_KERNEL_ARGS(instances, rays, count, results)
};

struct CastTrianglesArgs {
  static constexpr const char* kName = "cast_triangles";
  Global<const dev::Instance> instances;
  Global<const dev::Triangle> tris;
  cl_uint tri_count = 0, stride = 0;
  Global<const dev::f4> rays;
  cl_uint count = 0;
  Global<dev::f4> results;
  CLRT_KERNEL_ARGS(instances, tris, tri_count, stride, rays, count, results)
};

std::vector<DeviceHit> run_kernel(const std::vector<dev::Instance>& instances,
                                  const std::vector<WorldRay>& rays,
                                  const Global<dev::Triangle>* triangles, int count, int stride) {
  std::vector<dev::f4> packed;
  for (const WorldRay& ray : rays) {
    packed.push_back(to_f4(ray.origin, ray.tmin));
    packed.push_back(to_f4(ray.dir, ray.tmax));
  }
  const Global<dev::f4> results = allocate<dev::f4>(2 * rays.size(), "results");
  const auto ray_count = static_cast<cl_uint>(rays.size());
  if (triangles) {
    run(test_program(kKernels),
        CastTrianglesArgs{upload(instances), *triangles, static_cast<cl_uint>(count),
                          static_cast<cl_uint>(stride), upload(packed), ray_count, results},
        rays.size());
  } else {
    run(test_program(kKernels),
        CastCanonicalArgs{upload(instances), upload(packed), ray_count, results}, rays.size());
  }
  const std::vector<dev::f4> out = download(results, 2 * rays.size());
  std::vector<DeviceHit> hits(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const dev::f4 a = out[2 * i], b = out[2 * i + 1];
    hits[i] = {b.x != 0, a.w, {a.x, a.y, a.z}, b.y, b.z};
  }
  return hits;
}

// Whether the reference's answer is stable when the object shrinks or grows by a relative
// 1e-3: the same hit or miss, and no jump of t (to another surface, or past a cone's apex,
// where even the double-precision reference is unreliable).
bool well_conditioned(const PlacedShape& shape, const WorldRay& ray, const ReferenceHit& exact) {
  for (const double s : {1 - 1e-3, 1 + 1e-3}) {
    PlacedShape moved = shape;
    moved.transform = shape.transform * Mat4::scale({s, s, s});
    const ReferenceHit hit = reference_intersect(moved, ray);
    if (hit.hit != exact.hit) return false;
    if (hit.hit && std::abs(hit.t - exact.t) * length(ray.dir) > 0.1) return false;
  }
  return true;
}

std::string describe(const PlacedShape& shape, const WorldRay& ray, const ReferenceHit& expected,
                     const DeviceHit& got) {
  std::ostringstream out;
  out.precision(9);
  const auto v = [&](const Vec3& p) { out << '(' << p.x << ", " << p.y << ", " << p.z << ')'; };
  out << "shape " << shape.shape << " r0 " << shape.cone_r0 << " r1 " << shape.cone_r1
      << "\nM rows:";
  for (const auto& row : shape.transform.m)
    out << " [" << row[0] << ' ' << row[1] << ' ' << row[2] << ' ' << row[3] << ']';
  out << "\nray ";
  v(ray.origin);
  out << " + t ";
  v(ray.dir);
  out << " in (" << ray.tmin << ", " << ray.tmax << ")\nexpected hit " << expected.hit << " t "
      << expected.t << " n ";
  v(expected.normal);
  out << "\ndevice   hit " << got.hit << " t " << got.t << " n ";
  v(got.normal);
  return out.str();
}

}  // namespace

Vec3 round_to_float(const Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

dev::Instance make_instance(const PlacedShape& shape) {
  return instance_of(shape.transform, shape.shape, shape.cone_r0, shape.cone_r1);
}

std::vector<DeviceHit> cast_canonical(const std::vector<PlacedShape>& shapes,
                                      const std::vector<WorldRay>& rays) {
  std::vector<dev::Instance> instances;
  for (const PlacedShape& shape : shapes) instances.push_back(make_instance(shape));
  return run_kernel(instances, rays, nullptr, 0, 0);
}

std::vector<DeviceHit> cast_triangles(const std::vector<Vec3>& triangles, int count, int stride,
                                      const std::vector<Mat4>& transforms,
                                      const std::vector<WorldRay>& rays) {
  std::vector<dev::Instance> instances;
  for (const Mat4& m : transforms) instances.push_back(instance_of(m, CLRT_SHAPE_MESH, 1, 0));
  std::vector<dev::Triangle> packed;
  for (std::size_t i = 0; i + 2 < triangles.size(); i += 3)
    packed.push_back({to_f4(triangles[i], 0), to_f4(triangles[i + 1], 0), to_f4(triangles[i + 2], 0)});
  const Global<dev::Triangle> buffer = upload(packed);
  return run_kernel(instances, rays, &buffer, count, stride);
}

void check_hit(const DeviceHit& got, double t, const Vec3& normal) {
  REQUIRE(got.hit);
  CHECK(got.t == Approx(t).margin(1e-5));
  const Vec3 n = normalize(normal);
  INFO("normal (" << got.normal.x << ", " << got.normal.y << ", " << got.normal.z << ")");
  CHECK(length(got.normal - n) <= 1e-5);
}

void check_miss(const DeviceHit& got, const WorldRay& ray) {
  CHECK_FALSE(got.hit);
  CHECK(got.t == static_cast<float>(ray.tmax));
  CHECK(got.normal == kNormalSentinel);
}

int compare_with_reference(const std::vector<PlacedShape>& shapes,
                           const std::vector<WorldRay>& rays) {
  const std::vector<DeviceHit> device_hits = cast_canonical(shapes, rays);
  int compared = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const WorldRay& ray = rays[i];
    const ReferenceHit expected = reference_intersect(shapes[i], ray);
    const DeviceHit& got = device_hits[i];
    INFO(describe(shapes[i], ray, expected, got));
    // Whatever the case, no NaN and no hit outside (tmin, tmax).
    REQUIRE_FALSE(std::isnan(got.t));
    REQUIRE_FALSE((std::isnan(got.normal.x) || std::isnan(got.normal.y) || std::isnan(got.normal.z)));
    if (got.hit) REQUIRE((got.t > ray.tmin && got.t < ray.tmax));
    if (!well_conditioned(shapes[i], ray, expected)) continue;
    ++compared;
    REQUIRE(got.hit == expected.hit);
    if (!got.hit) {
      check_miss(got, ray);
      continue;
    }
    // Float rounding moves the surface by about 1e-7 of the scene's size across itself;
    // along the ray that is 1 / cos(incidence) times more.
    const double speed = length(ray.dir);
    const double incidence = std::abs(dot(expected.normal, ray.dir)) / speed;
    CHECK(std::abs(got.t - expected.t) * speed <=
          1e-5 * (1 + expected.t * speed + length(ray.origin)) / std::max(incidence, 1e-3));
    if (expected.edge_distance > 1e-3) CHECK(length(got.normal - expected.normal) <= 2e-3);
  }
  return compared;
}

}  // namespace clrt::test
