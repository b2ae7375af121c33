#include "render/busy_timeline.hpp"

#include <algorithm>

namespace clrt {

void BusyTimeline::add(std::uint64_t start_ns, std::uint64_t end_ns, const char* kernel) {
  std::lock_guard<std::mutex> lock(mutex_);
  intervals_.push_back({start_ns, std::max(start_ns, end_ns), kernel});
}

DeviceTime BusyTimeline::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  // A sweep over the intervals' ends: between two consecutive ends the set of running kernels
  // is fixed, and the segment is split equally among them.
  struct End {
    std::uint64_t at;
    bool opens;
    std::size_t interval;
  };
  std::vector<End> ends;
  ends.reserve(2 * intervals_.size());
  for (std::size_t i = 0; i < intervals_.size(); ++i) {
    ends.push_back({intervals_[i].start, true, i});
    ends.push_back({intervals_[i].end, false, i});
  }
  // At one instant: by interval, and an interval's start before its end (it may be empty).
  std::sort(ends.begin(), ends.end(), [](const End& a, const End& b) {
    if (a.at != b.at) return a.at < b.at;
    if (a.interval != b.interval) return a.interval < b.interval;
    return a.opens && !b.opens;
  });
  std::vector<double> share_ns(intervals_.size(), 0.0);
  std::vector<std::size_t> running;
  double busy_ns = 0;
  std::uint64_t previous = ends.empty() ? 0 : ends.front().at;
  for (const End& e : ends) {
    if (!running.empty() && e.at > previous) {
      const auto segment = static_cast<double>(e.at - previous);
      busy_ns += segment;
      for (std::size_t i : running) share_ns[i] += segment / static_cast<double>(running.size());
    }
    previous = e.at;
    if (e.opens)
      running.push_back(e.interval);
    else
      running.erase(std::find(running.begin(), running.end(), e.interval));
  }
  DeviceTime time;
  time.busy_seconds = busy_ns * 1e-9;
  for (std::size_t i = 0; i < intervals_.size(); ++i)
    time.kernel_share_seconds[intervals_[i].kernel] += share_ns[i] * 1e-9;
  intervals_.clear();
  return time;
}

}  // namespace clrt
