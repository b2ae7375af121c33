// When a device was busy: the execution intervals of every kernel the lanes of one device
// launched, on the device's own clock. Lanes overlap, so the busy time is the union of the
// intervals, not their sum; it is what "device busy" in --stats divides by the render time.
// The same overlap makes a kernel's own interval hold time it spent waiting for a core while
// another lane's kernel ran: each kernel's share divides every moment equally among the kernels
// running then, so the shares add up to the busy time.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace clrt {

struct DeviceTime {
  double busy_seconds = 0;
  std::map<std::string, double> kernel_share_seconds;
};

class BusyTimeline {
 public:
  // `kernel` must outlive the timeline (the kernels' names are static).
  void add(std::uint64_t start_ns, std::uint64_t end_ns, const char* kernel);  // thread-safe
  // The busy time and each kernel's share since the last take; clears the intervals.
  DeviceTime take();

 private:
  struct Interval {
    std::uint64_t start, end;
    const char* kernel;
  };
  std::mutex mutex_;
  std::vector<Interval> intervals_;
};

}  // namespace clrt
