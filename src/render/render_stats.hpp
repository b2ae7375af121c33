// What --stats reports: rays by kind, per-pass queue sizes and device times, per-kernel device
// times, and the wall-clock split of the whole command.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "shared/ray.h"

namespace clrt {

// One device that took part, as an experiment needs to name it.
struct DeviceReport {
  std::string platform, name, driver, opencl_c, device_class;
  std::size_t local_size = 0;
  std::uint64_t wavefront = 0;  // rays per queue (camera samples per wave where there are no queues)
  std::uint32_t lanes = 0;      // waves in flight
  double busy_seconds = 0;      // time some kernel of this device was executing
  std::uint64_t camera_samples = 0;  // camera samples it traced: its share of the frame
};

struct PassStats {
  std::uint64_t rays = 0;         // rays in the queue at this pass (all waves)
  std::uint64_t shadow_rays = 0;  // compacted shadow rays tested in this pass
  std::uint64_t max_queue = 0;    // the largest queue of any wave at this pass
  double device_seconds = 0;      // device time of every kernel launched for this pass
};

struct KernelStats {
  std::uint64_t launches = 0;
  double device_seconds = 0;  // the sum of its launches' intervals
  // Its share of the device's busy time: where kernels of several lanes ran at once, each had
  // an equal part of that time (BusyTimeline). The shares add up to the busy time.
  double share_seconds = 0;
};

// "camera", "reflection", "refraction", "shadow": CLRT_RAY_* in order.
const char* ray_kind_name(unsigned kind);

struct RenderStats {
  std::string scene, integrator, version;
  std::uint64_t width = 0, height = 0;     // the rendered region's size
  std::uint64_t samples_per_pixel = 0;
  std::uint64_t sample_rounds = 0;  // the most rounds a region took them in (sample_rounds.hpp)
  std::uint64_t frames = 1;
  std::vector<DeviceReport> devices;
  std::array<std::uint64_t, CLRT_RAY_KINDS> rays{};  // by kind, CLRT_RAY_*
  std::vector<PassStats> passes;  // index = pass = ray depth (wavefront only)
  std::map<std::string, KernelStats> kernels;
  std::uint64_t waves = 0, wave_restarts = 0;
  std::uint64_t device_bytes = 0;    // render buffers + scene tables
  std::uint64_t peak_host_bytes = 0; // the process's peak resident memory
  std::uint64_t geometry_bytes = 0;  // instance, mesh and triangle tables and BVH nodes
  std::uint64_t bvh_bytes = 0;       // of which the BVH table (nodes and leaf data)
  double load_seconds = 0, bvh_seconds = 0, build_seconds = 0, render_seconds = 0,
         write_seconds = 0, total_seconds = 0;

  std::uint64_t total_rays() const;
  std::uint64_t camera_samples() const { return rays[CLRT_RAY_CAMERA]; }
  double device_seconds() const;  // the sum over kernels
  // Frames over the time spent rendering and writing them.
  double frames_per_second() const;
  // The share of the render time the devices were executing kernels (their mean).
  double device_busy() const;
  // The share of the camera samples of these stats that `device` (one of `devices`) traced.
  double frame_share(const DeviceReport& device) const;
  // Another device's share of the same render (its rays, passes, kernels and buffers).
  void merge(const RenderStats& other);
  std::string to_text() const;
  nlohmann::json to_json() const;
};

}  // namespace clrt
