#include "clrt_tracer.hpp"

#include <chrono>

#include "device/launch.hpp"
#include "shared/scene.h"

namespace clrt::compare {
namespace {

dev::f4 f4_of(const float v[3], float w) { return {v[0], v[1], v[2], w}; }

template <typename T>
compute::buffer upload(DeviceContext& device, const std::vector<T>& items, const char* what) {
  compute::buffer buffer = device.allocate(sizeof(T) * items.size(), what);
  if (!items.empty())
    device.queue().enqueue_write_buffer(buffer, 0, sizeof(T) * items.size(), items.data());
  return buffer;
}

template <typename T>
std::vector<T> download(DeviceContext& device, const compute::buffer& buffer, std::size_t count) {
  std::vector<T> items(count);
  if (count) device.queue().enqueue_read_buffer(buffer, 0, sizeof(T) * count, items.data());
  return items;
}

}  // namespace

ClrtTracer::ClrtTracer(DeviceContext& device, const compute::program& program,
                       const GeometryData& geometry)
    : device_(device),
      geometry_(device, geometry),
      intersect_(program, "intersect"),
      shadow_(program, "shadow") {
  // The kernels read only params->epsilon.
  dev::RenderParams params{};
  params.epsilon = kTmin;
  params_ = upload(device, std::vector<dev::RenderParams>{params}, "render parameters");
  for (compute::kernel* k : {&intersect_, &shadow_}) {
    first_arg_ = geometry_.bind(*k, 0);
    k->set_arg(first_arg_, params_);
  }
}

ClrtBatch ClrtTracer::closest_batch(const RaySet& set) {
  std::vector<dev::Ray> rays;
  rays.reserve(set.rays.size());
  for (const HostRay& r : set.rays)
    rays.push_back({f4_of(r.origin, 0), f4_of(r.dir, 0), {1, 1, 1, 0}, 0, 0, 0, CLRT_RAY_CAMERA});
  return {&intersect_, upload(device_, rays, "rays"),
          device_.allocate(sizeof(dev::Hit) * rays.size(), "hits"), rays.size(), compute::buffer()};
}

ClrtBatch ClrtTracer::occlusion_batch(const RaySet& set) {
  std::vector<dev::ShadowRay> rays;
  rays.reserve(set.rays.size());
  for (const HostRay& r : set.rays)
    rays.push_back({f4_of(r.origin, r.tmax), f4_of(r.dir, 0), {1, 1, 1, 0}, 0, {0, 0, 0}});
  return {&shadow_, upload(device_, rays, "shadow rays"),
          device_.allocate(sizeof(dev::f4) * rays.size(), "visibility"), rays.size(),
          upload(device_, std::vector<dev::u32>{static_cast<dev::u32>(rays.size())}, "count")};
}

double ClrtTracer::launch(ClrtBatch& batch) {
  batch.kernel->set_arg(first_arg_ + 1, batch.rays);
  if (batch.count_on_device.get()) {
    batch.kernel->set_arg(first_arg_ + 2, batch.count_on_device);
  } else {
    batch.kernel->set_arg(first_arg_ + 2, static_cast<cl_uint>(batch.count));
  }
  batch.kernel->set_arg(first_arg_ + 3, batch.results);
  compute::event done = clrt::launch(device_.queue(), *batch.kernel, batch.count);
  if (batch.count == 0) return 0;
  done.wait();
  return done.duration<std::chrono::duration<double>>().count();
}

std::vector<dev::Hit> ClrtTracer::hits(const ClrtBatch& closest) {
  return download<dev::Hit>(device_, closest.results, closest.count);
}

std::vector<char> ClrtTracer::blocked(const ClrtBatch& occlusion) {
  std::vector<char> out;
  out.reserve(occlusion.count);
  // The shadow kernel writes the ray's contribution, (1, 1, 1), when nothing blocks it.
  for (const dev::f4& v : download<dev::f4>(device_, occlusion.results, occlusion.count))
    out.push_back(v.x == 0.0f);
  return out;
}

}  // namespace clrt::compare
