// When a device was busy: the execution intervals of every kernel the lanes of one device
// launched, on the device's own clock. Lanes overlap, so the busy time is the union of the
// intervals, not their sum; it is what "device busy" in --stats divides by the render time.
#pragma once

#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace clrt {

class BusyTimeline {
 public:
  void add(std::uint64_t start_ns, std::uint64_t end_ns);  // thread-safe
  // Seconds covered by at least one interval; clears them.
  double take_busy_seconds();

 private:
  std::mutex mutex_;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> intervals_;
};

}  // namespace clrt
