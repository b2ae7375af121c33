// A render takes each pixel's samples in rounds over its whole region: round r takes samples
// [first, first + count) of every pixel, so a path-traced picture fills in as it converges and
// the progress display can count samples per pixel. Between rounds each pixel's running sum is
// kept on the host (16 bytes a pixel); kernels/accumulate.cl's resolve adds the next round's
// samples to it in sample order, so the split into rounds never changes a bit of the image, and
// a render may stop after any round and go on later from its sums (clrt --resume), with the
// bits of one that never stopped. The host divides the sums by the sample count.
#pragma once

#include <cstdint>
#include <vector>

#include "render/pixel_store.hpp"

namespace clrt {

struct SampleRound {
  std::uint32_t first = 0, count = 0;
  std::uint32_t total = 0;  // samples per pixel of the render
  bool last() const { return first + count == total; }
};

// At most kMaxSampleRounds rounds, each of at least enough camera rays to keep
// `rays_in_flight` (every lane's wavefront) busy several times over, so that the wait for a
// round's last wave stays small; a render of one sample per pixel is one round. Rounds start
// at sample `first` (those before it were taken earlier: a resumed render); none when
// first == samples.
constexpr std::uint32_t kMaxSampleRounds = 64;
std::vector<SampleRound> sample_rounds(std::uint32_t samples, std::uint64_t region_pixels,
                                       std::uint64_t rays_in_flight, std::uint32_t first = 0);

// The mean of `count` pixels' sums of `samples` samples each, as every render divides them.
std::vector<dev::f4> mean_of_sums(const dev::f4* sums, std::uint64_t count, std::uint32_t samples);

// Where one round's resolved pixels go: the running sums until the last round (and after it
// too when `keep_sums`, for a render that may go on later), their mean after the last round to
// the store; and, when there is one, to a watcher (clrt --preview), which is shown the mean so
// far after each round. Lanes write disjoint runs of pixels, so no lock is needed.
class RoundOutput {
 public:
  RoundOutput(const SampleRound& round, std::vector<dev::f4>& sums, PixelStore& store,
              PixelStore* watcher = nullptr, bool keep_sums = false)
      : round_(round), sums_(sums), store_(store), watcher_(watcher), keep_sums_(keep_sums) {}

  const SampleRound& round() const { return round_; }
  // The sums of the samples before this round for pixels [first, ...); not for the first round.
  const dev::f4* sums_before(std::uint64_t first) const { return sums_.data() + first; }
  void take(std::uint64_t first, std::uint32_t count, const dev::f4* pixels);

 private:
  SampleRound round_;
  std::vector<dev::f4>& sums_;
  PixelStore& store_;
  PixelStore* watcher_;
  bool keep_sums_;
};

}  // namespace clrt
