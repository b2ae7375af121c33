#include "clrt_tracer.hpp"

#include <chrono>
#include <utility>

#include "device/device_profile.hpp"
#include "device/transfer.hpp"
#include "shared/scene.h"

namespace clrt::compare {
namespace {

dev::f4 f4_of(const float v[3], float w) { return {v[0], v[1], v[2], w}; }

// The kernels read only params->epsilon.
dev::RenderParams tracing_params() {
  dev::RenderParams params{};
  params.epsilon = kTmin;
  return params;
}

}  // namespace

ClrtTracer::ClrtTracer(DeviceContext& device, const compute::program& program,
                       GeometryData geometry)
    : device_(device),
      geometry_(device, std::make_shared<const GeometryData>(std::move(geometry))),
      params_(upload(device, std::vector<dev::RenderParams>{tracing_params()}, "render parameters")),
      intersect_(program),
      shadow_(program),
      local_size_(device_profile(device.device()).local_size) {}

ClrtBatch ClrtTracer::closest_batch(const RaySet& set) {
  std::vector<dev::Ray> rays;
  rays.reserve(set.rays.size());
  for (const HostRay& r : set.rays)
    rays.push_back({{r.origin[0], r.origin[1], r.origin[2]}, 1, {r.dir[0], r.dir[1], r.dir[2]}, 0,
                    {1, 1, 1}, 0, 0, 0, 0, CLRT_RAY_CAMERA});
  ClrtBatch batch;
  batch.count = rays.size();
  batch.closest = {geometry_.args(), params_, upload(device_, rays, "rays"),
                   static_cast<cl_uint>(rays.size()), allocate<dev::Hit>(device_, rays.size(), "hits")};
  return batch;
}

ClrtBatch ClrtTracer::occlusion_batch(const RaySet& set) {
  std::vector<dev::ShadowRay> rays;
  rays.reserve(set.rays.size());
  for (const HostRay& r : set.rays)
    rays.push_back({f4_of(r.origin, r.tmax), f4_of(r.dir, 0), {1, 1, 1, 0}, 0, 0.0f, {0, 0}});
  ClrtBatch batch;
  batch.occlusion = true;
  batch.count = rays.size();
  batch.shadow = {geometry_.args(), params_, upload(device_, rays, "shadow rays"),
                  upload(device_, std::vector<cl_uint>{static_cast<cl_uint>(rays.size())}, "count"),
                  allocate<dev::f4>(device_, rays.size(), "visibility")};
  return batch;
}

double ClrtTracer::launch(ClrtBatch& batch) {
  if (batch.count == 0) return 0;
  compute::event done =
      batch.occlusion ? shadow_.launch(device_.queue(), batch.shadow, batch.count, local_size_)
                      : intersect_.launch(device_.queue(), batch.closest, batch.count, local_size_);
  done.wait();
  return done.duration<std::chrono::duration<double>>().count();
}

std::vector<dev::Hit> ClrtTracer::hits(const ClrtBatch& closest) {
  return download(device_, closest.closest.hits, closest.count);
}

std::vector<char> ClrtTracer::blocked(const ClrtBatch& occlusion) {
  std::vector<char> out;
  out.reserve(occlusion.count);
  // The shadow kernel writes the ray's contribution, (1, 1, 1), when nothing blocks it.
  for (const dev::f4& v : download(device_, occlusion.shadow.visible, occlusion.count))
    out.push_back(v.x == 0.0f);
  return out;
}

}  // namespace clrt::compare
