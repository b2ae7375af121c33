// What --stats reports: rays by kind, per-pass queue sizes and device times, per-kernel device
// times, and the wall-clock split of the whole command.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace clrt {

struct PassStats {
  std::uint64_t rays = 0;         // rays in the queue at this pass (all waves)
  std::uint64_t shadow_rays = 0;  // compacted shadow rays tested in this pass
  std::uint64_t max_queue = 0;    // the largest queue of any wave at this pass
  double device_seconds = 0;      // device time of every kernel launched for this pass
};

struct KernelStats {
  std::uint64_t launches = 0;
  double device_seconds = 0;
};

struct RenderStats {
  std::string device;
  std::uint64_t camera_rays = 0, reflection_rays = 0, refraction_rays = 0, shadow_rays = 0;
  std::vector<PassStats> passes;  // index = pass = ray depth
  std::map<std::string, KernelStats> kernels;
  std::uint64_t waves = 0, wave_restarts = 0;
  std::uint64_t wavefront = 0;       // rays per queue
  std::uint64_t device_bytes = 0;    // render buffers + scene tables
  std::uint64_t peak_host_bytes = 0; // the process's peak resident memory
  std::uint64_t geometry_bytes = 0;  // instance, mesh and triangle tables and BVH nodes
  std::uint64_t bvh_bytes = 0;       // of which the BVH table (nodes and leaf data)
  double load_seconds = 0, bvh_seconds = 0, build_seconds = 0, render_seconds = 0,
         write_seconds = 0, total_seconds = 0;

  std::uint64_t total_rays() const {
    return camera_rays + reflection_rays + refraction_rays + shadow_rays;
  }
  void merge(const RenderStats& other);  // another device's share of the same render
  std::string to_text() const;
  std::string to_json() const;
};

}  // namespace clrt
