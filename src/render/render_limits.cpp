#include "render/render_limits.hpp"

#include <algorithm>

#include "geometry/emitter_table.hpp"
#include "render/integrator.hpp"
#include "render/render_tuning.hpp"
#include "render/wave_sizes.hpp"
#include "scene/limits.hpp"
#include "scene/memory_limit.hpp"
#include "scene/scene_memory.hpp"

namespace clrt {
namespace {

// Host bytes per pixel: the linear float image (12), its 8-bit copy (4) and the encoded file
// (up to 12 for PFM), and with more than one sample per pixel the running sums between rounds
// of samples (16: render/sample_rounds.hpp).
constexpr std::uint64_t kHostBytesPerPixel = 28;
constexpr std::uint64_t kRoundSumBytesPerPixel = sizeof(dev::f4);

[[noreturn]] void refuse(int exit_code, const std::string& message) {
  throw RenderLimitError(exit_code, message);
}

void check_request(const Scene& scene, const RenderOptions& o) {
  const std::int64_t width = o.width, height = o.height;
  if (width < 1 || height < 1 || width > limits::kMaxImageSide || height > limits::kMaxImageSide)
    refuse(2, "the image size " + std::to_string(width) + "x" + std::to_string(height) +
                  " is beyond the limit: each side must be from 1 to " +
                  std::to_string(limits::kMaxImageSide));
  if (width * height > limits::kMaxPixels)
    refuse(2, "the image size " + std::to_string(width) + "x" + std::to_string(height) + " is " +
                  std::to_string(width * height) + " pixels, more than the limit of " +
                  std::to_string(limits::kMaxPixels));
  if (o.samples < 1 || o.samples > limits::kMaxSamples)
    refuse(2, std::to_string(o.samples) + " samples per pixel is beyond the limit: from 1 to " +
                  std::to_string(limits::kMaxSamples));
  if (o.max_depth < 0 || o.max_depth > limits::kMaxDepth)
    refuse(2, "a maximum depth of " + std::to_string(o.max_depth) +
                  " is beyond the limit: from 0 to " + std::to_string(limits::kMaxDepth));
  std::int64_t shadow = 0;
  for (const LightSpec& light : scene.lights) {
    if (shadow_samples(light) > limits::kMaxLightSamples)
      refuse(2, "an area light takes " + std::to_string(light.samples) +
                    " samples, more than the limit of " + std::to_string(limits::kMaxLightSamples));
    shadow += shadow_samples(light);
  }
  if (shadow > limits::kMaxShadowSamples)
    refuse(2, "the lights take " + std::to_string(shadow) +
                  " shadow-ray samples per shading point, more than the limit of " +
                  std::to_string(limits::kMaxShadowSamples));
}

// As make_frame counts them: path mode's glow light and environment take one each (at most:
// an environment that is black everywhere takes none).
std::uint64_t shadow_samples_per_point(const Scene& scene, const RenderOptions& o) {
  std::uint64_t sum = 0;
  for (const LightSpec& light : scene.lights) sum += static_cast<std::uint64_t>(shadow_samples(light));
  if (o.mode == RenderMode::Path) sum += (glow_is_sampled(scene) ? 1 : 0) + (scene.environment ? 1 : 0);
  return sum;
}

std::uint64_t pixel_count(const RenderOptions& o) {
  return static_cast<std::uint64_t>(o.width) * static_cast<std::uint64_t>(o.height);
}

// The device bytes of one device's render; refuses a buffer the device cannot allocate.
std::uint64_t check_device(const Scene& scene, const RenderOptions& o, const DeviceBudget& device,
                           std::uint64_t geometry_bytes) {
  const WaveSizes sizes = wave_sizes(device.wavefront, static_cast<std::uint64_t>(o.samples),
                                     shadow_samples_per_point(scene, o));
  std::uint64_t queues = 0;
  for (const DeviceBuffer& buffer : integrator_entry(o.integrator).buffers(sizes)) {
    if (buffer.bytes > device.max_allocation)
      refuse(1, "the " + buffer.what + " buffer needs " + mebibytes(buffer.bytes) + " on " + device.name +
                    ", more than its largest allocation (" + mebibytes(device.max_allocation) +
                    "): lower --wavefront (now " + std::to_string(device.wavefront) + ")" +
                    (sizes.shade_chunk == 1 ? " or the lights' samples" : ""));
    queues += buffer.bytes;
  }
  // Every lane has queues of its own.
  const std::uint64_t total = geometry_bytes + queues * device.lanes;
  if (total > device.global_memory)
    refuse(1, "the render needs about " + mebibytes(total) + " of memory on " + device.name +
                  " (scene " + mebibytes(geometry_bytes) + ", queues " + mebibytes(total - geometry_bytes) +
                  "), more than its " + mebibytes(device.global_memory) + ": lower --wavefront");
  return total;
}

}  // namespace

MachineBudget measure_budget(const std::vector<DeviceEntry>& devices, const RenderOptions& options) {
  MachineBudget budget;
  budget.host_available = memory_limit().bytes;
  for (const DeviceEntry& entry : devices) {
    DeviceBudget d;
    d.name = entry.device.name();
    const DeviceProfile tuning = render_tuning(entry.device, options);
    d.wavefront = tuning.wavefront;
    d.lanes = tuning.lanes;
    d.max_allocation = entry.device.get_info<cl_ulong>(CL_DEVICE_MAX_MEM_ALLOC_SIZE);
    d.global_memory = entry.device.get_info<cl_ulong>(CL_DEVICE_GLOBAL_MEM_SIZE);
    d.uses_host_memory = entry.device.get_info<cl_bool>(CL_DEVICE_HOST_UNIFIED_MEMORY) == CL_TRUE;
    budget.devices.push_back(d);
  }
  return budget;
}

void check_render_limits(const Scene& scene, const RenderOptions& options,
                         const MachineBudget& budget) {
  check_request(scene, options);
  const std::uint64_t geometry = estimated_geometry_bytes(scene);
  const std::uint64_t image =
      pixel_count(options) *
      (kHostBytesPerPixel + (options.samples > 1 ? kRoundSumBytesPerPixel : 0));
  // The host holds the image and builds the geometry tables (which it keeps while they upload),
  // and gives its memory to every device that has none of its own.
  std::uint64_t host = image + geometry;
  for (const DeviceBudget& device : budget.devices) {
    const std::uint64_t on_device = check_device(scene, options, device, geometry);
    if (device.uses_host_memory) host += on_device;
  }
  if (host > budget.host_available)
    refuse(1, "the render needs about " + mebibytes(host) + " of host memory (image " + mebibytes(image) +
                  ", scene " + mebibytes(geometry) + "), more than the " + mebibytes(budget.host_available) +
                  " available");
}

}  // namespace clrt
