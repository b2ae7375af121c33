// The device's busy time and each kernel's share of it, against a count made nanosecond by
// nanosecond on hand-made and random intervals.
#include <catch2/catch.hpp>

#include <map>
#include <random>
#include <string>
#include <vector>

#include "render/busy_timeline.hpp"

using clrt::BusyTimeline;
using clrt::DeviceTime;

namespace {

struct Run {
  std::uint64_t start, end;
  const char* kernel;
};

// Every nanosecond t in [start, end) of the runs that cover it, split equally among them.
DeviceTime counted(const std::vector<Run>& runs) {
  DeviceTime time;
  std::uint64_t last = 0;
  for (const Run& r : runs) last = std::max(last, r.end);
  for (std::uint64_t t = 0; t < last; ++t) {
    std::vector<const char*> on;
    for (const Run& r : runs)
      if (r.start <= t && t < r.end) on.push_back(r.kernel);
    if (on.empty()) continue;
    time.busy_seconds += 1e-9;
    for (const char* k : on) time.kernel_share_seconds[k] += 1e-9 / static_cast<double>(on.size());
  }
  return time;
}

DeviceTime swept(const std::vector<Run>& runs) {
  BusyTimeline timeline;
  for (const Run& r : runs) timeline.add(r.start, r.end, r.kernel);
  return timeline.take();
}

void check_same(const DeviceTime& a, const DeviceTime& b) {
  CHECK(a.busy_seconds == Approx(b.busy_seconds).epsilon(1e-9));
  for (const auto& [kernel, seconds] : b.kernel_share_seconds) {
    INFO(kernel);
    CHECK(a.kernel_share_seconds.at(kernel) == Approx(seconds).epsilon(1e-9).margin(1e-15));
  }
}

}  // namespace

TEST_CASE("overlapping kernels share the time they run together", "[busy]") {
  // shade alone 0-5, with shadow 5-10, shadow alone 10-15, idle, compact alone 20-25.
  const std::vector<Run> runs = {{0, 10, "shade"}, {5, 15, "shadow"}, {20, 25, "compact"}};
  const DeviceTime t = swept(runs);
  CHECK(t.busy_seconds == Approx(20e-9));
  CHECK(t.kernel_share_seconds.at("shade") == Approx(7.5e-9));
  CHECK(t.kernel_share_seconds.at("shadow") == Approx(7.5e-9));
  CHECK(t.kernel_share_seconds.at("compact") == Approx(5e-9));
  check_same(t, counted(runs));
}

TEST_CASE("empty, nested and repeated intervals", "[busy]") {
  const std::vector<Run> runs = {{3, 3, "empty"},  {0, 12, "outer"}, {2, 4, "inner"},
                                 {2, 4, "inner"},  {12, 12, "edge"}, {12, 14, "after"}};
  const DeviceTime t = swept(runs);
  CHECK(t.kernel_share_seconds.at("empty") == 0);
  CHECK(t.kernel_share_seconds.at("edge") == 0);
  check_same(t, counted(runs));
}

TEST_CASE("random lanes of kernels agree with the count", "[busy]") {
  std::mt19937 random(7);
  const char* const names[] = {"a", "b", "c", "d"};
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Run> runs;
    for (int lane = 0; lane < 3; ++lane) {
      std::uint64_t at = random() % 20;
      for (int k = 0; k < 8; ++k) {
        const std::uint64_t length = random() % 30;
        runs.push_back({at, at + length, names[random() % 4]});
        at += length + random() % 10;
      }
    }
    INFO("trial " << trial);
    check_same(swept(runs), counted(runs));
  }
}

TEST_CASE("a take clears the timeline", "[busy]") {
  BusyTimeline timeline;
  timeline.add(0, 10, "k");
  CHECK(timeline.take().busy_seconds == Approx(10e-9));
  const DeviceTime again = timeline.take();
  CHECK(again.busy_seconds == 0);
  CHECK(again.kernel_share_seconds.empty());
}
