#include "render/sample_rounds.hpp"

#include <algorithm>
#include <vector>

namespace clrt {
namespace {

std::uint64_t ceil_div(std::uint64_t a, std::uint64_t b) { return (a + b - 1) / b; }

// Rays a round should hold per ray in flight: a round ending with one lane still on its last
// wave then idles the others for at most about a quarter of the round.
constexpr std::uint64_t kWavesPerRound = 4;

}  // namespace

std::vector<SampleRound> sample_rounds(std::uint32_t samples, std::uint64_t region_pixels,
                                       std::uint64_t rays_in_flight, std::uint32_t first) {
  const std::uint64_t fewest = ceil_div(samples, kMaxSampleRounds);
  const std::uint64_t filling =
      ceil_div(kWavesPerRound * std::max<std::uint64_t>(1, rays_in_flight),
               std::max<std::uint64_t>(1, region_pixels));
  const auto per_round =
      static_cast<std::uint32_t>(std::min<std::uint64_t>(samples, std::max(fewest, filling)));
  std::vector<SampleRound> rounds;
  for (; first < samples; first += per_round)
    rounds.push_back({first, std::min(per_round, samples - first), samples});
  return rounds;
}

std::vector<dev::f4> mean_of_sums(const dev::f4* sums, std::uint64_t count, std::uint32_t samples) {
  const float n = static_cast<float>(samples);
  std::vector<dev::f4> mean(sums, sums + count);
  for (dev::f4& p : mean) p = {p.x / n, p.y / n, p.z / n, p.w / n};
  return mean;
}

void RoundOutput::take(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) {
  if (!round_.last() || keep_sums_)
    std::copy(pixels, pixels + count, sums_.begin() + static_cast<std::ptrdiff_t>(first));
  if (!round_.last() && !watcher_) return;
  const std::vector<dev::f4> mean = mean_of_sums(pixels, count, round_.first + round_.count);
  if (round_.last()) store_.store(first, count, mean.data());
  if (watcher_) watcher_->store(first, count, mean.data());
}

}  // namespace clrt
