#include "render/busy_timeline.hpp"

#include <algorithm>

namespace clrt {

void BusyTimeline::add(std::uint64_t start_ns, std::uint64_t end_ns) {
  std::lock_guard<std::mutex> lock(mutex_);
  intervals_.emplace_back(start_ns, std::max(start_ns, end_ns));
}

double BusyTimeline::take_busy_seconds() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::sort(intervals_.begin(), intervals_.end());
  std::uint64_t busy = 0, covered_to = 0;
  for (const auto& [start, end] : intervals_) {
    const std::uint64_t from = std::max(start, covered_to);
    if (end > from) busy += end - from;
    covered_to = std::max(covered_to, end);
  }
  intervals_.clear();
  return static_cast<double>(busy) * 1e-9;
}

}  // namespace clrt
