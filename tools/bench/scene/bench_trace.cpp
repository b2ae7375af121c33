#include "bench_trace.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include <sys/resource.h>

#include "device/kernel_source.hpp"
#include "device/device_profile.hpp"
#include "device/transfer.hpp"
#include "geometry/bvh_builder.hpp"
#include "shared/ray.h"

namespace clrt::bench {
namespace {

const char* const kSource = "#include \"geometry/bvh_query_kernels.h\"\n";

constexpr float kTmin = 1e-4f;

void add_ray(RaySet& rays, const Vec3& o, const Vec3& d) {
  rays.push_back({static_cast<float>(o.x), static_cast<float>(o.y), static_cast<float>(o.z), kTmin});
  rays.push_back({static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z), INFINITY});
}

// CPU time of the whole process (the device's worker threads included).
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

Vec3 centre(const Box& b) { return {b.center(0), b.center(1), b.center(2)}; }

}  // namespace

Box scene_bounds(const GeometryData& geometry) {
  Box b;
  for (int k = 0; k < CLRT_BVH_WIDTH; ++k) b.grow(lane_box(geometry.nodes.at(0), k));
  if (b.empty()) b.grow(-1, -1, -1), b.grow(1, 1, 1);
  return b;
}

CameraSpec camera_for(const Box& bounds) {
  const Vec3 size{bounds.hi[0] - bounds.lo[0], bounds.hi[1] - bounds.lo[1], bounds.hi[2] - bounds.lo[2]};
  CameraSpec camera;
  camera.lookat = centre(bounds);
  camera.eye = camera.lookat + normalize(Vec3{0.3, 0.5, 1}) * (1.2 * length(size));
  camera.fov_degrees = 50;
  return camera;
}

RaySet camera_rays(const CameraSpec& camera, int count) {
  const int side = std::max(1, static_cast<int>(std::sqrt(count)));
  const Vec3 forward = normalize(camera.lookat - camera.eye);
  const Vec3 right = normalize(cross(forward, camera.up));
  const Vec3 up = cross(right, forward);
  const double half = std::tan(camera.fov_degrees * M_PI / 360);
  RaySet rays;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const double x = (2 * (i + 0.5) / side - 1) * half, y = (1 - 2 * (j + 0.5) / side) * half;
      add_ray(rays, camera.eye, normalize(forward + right * x + up * y));
    }
  return rays;
}

RaySet random_rays(const Box& bounds, int count) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  RaySet rays;
  while (static_cast<int>(rays.size()) < 2 * count) {
    const Vec3 o{bounds.lo[0] + u(rng) * (bounds.hi[0] - bounds.lo[0]),
                 bounds.lo[1] + u(rng) * (bounds.hi[1] - bounds.lo[1]),
                 bounds.lo[2] + u(rng) * (bounds.hi[2] - bounds.lo[2])};
    const Vec3 d{2 * u(rng) - 1, 2 * u(rng) - 1, 2 * u(rng) - 1};
    if (dot(d, d) > 1 || dot(d, d) < 1e-4) continue;
    add_ray(rays, o, normalize(d));
  }
  return rays;
}

Tracer::Tracer(DeviceContext& device, std::shared_ptr<const GeometryData> geometry)
    : device_(device),
      geometry_(device, std::move(geometry)),
      program_(device.build(assemble_kernel_source(kSource, "bench_bvh.cl"))),
      closest_(program_),
      any_(program_),
      local_size_(device_profile(device.device()).local_size) {}

Throughput Tracer::closest_hit_mrays(const RaySet& rays, int runs) {
  return measure(closest_, &BvhClosestHitsArgs::hits, rays, runs);
}

Throughput Tracer::any_hit_mrays(const RaySet& rays, int runs) {
  return measure(any_, &BvhAnyHitsArgs::results, rays, runs);
}

template <class Args, class Result>
Throughput Tracer::measure(TypedKernel<Args>& kernel, Global<Result> Args::*results,
                           const RaySet& rays, int runs) {
  const std::size_t count = rays.size() / 2;
  Args args;
  args.scene = geometry_.args();
  args.rays = upload(device_, rays, "rays");
  args.count = static_cast<cl_uint>(count);
  args.*results = allocate<Result>(device_, count, "results");
  Throughput best;
  for (int run = 0; run <= runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_seconds();
    kernel.launch(device_.queue(), args, count, local_size_);
    device_.queue().finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = cpu_seconds() - cpu_start;
    if (run == 0) continue;
    best.wall = std::max(best.wall, count / seconds * 1e-6);
    best.per_core = std::max(best.per_core, count / cpu * 1e-6);
  }
  return best;
}

}  // namespace clrt::bench
