#include "render/wave_loop.hpp"

#include <algorithm>
#include <string>

namespace clrt {

WaveLoop::WaveLoop(DeviceContext& device, const compute::program& program,
                   const DeviceFrame& frame, const IntegratorConfig& config,
                   const WaveSizes& sizes, std::uint32_t passes)
    : frame_(frame),
      capacity_(static_cast<std::uint32_t>(sizes.capacity)),
      wave_rays_(capacity_),
      resolver_(device, program, capacity_, static_cast<std::uint32_t>(sizes.wave_pixels),
                frame.host.params.max_sample_value),
      launcher_(device, config.local_size, config.profile),
      profiler_(launcher_, program, config.profile, passes,
                capacity_ / Profiler::kCountChunk + 1, config.timeline) {}

std::vector<DeviceBuffer> WaveLoop::with_resolver(std::vector<DeviceBuffer> own,
                                                  const WaveSizes& sizes) {
  for (DeviceBuffer& b : WaveResolver::buffers(sizes.capacity, sizes.wave_pixels))
    own.push_back(std::move(b));
  return own;
}

std::uint32_t WaveLoop::pixels_per_wave(std::uint32_t samples) const {
  return std::max<std::uint32_t>(1, wave_rays_ / samples);
}

void WaveLoop::render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) {
  const std::uint64_t total = rect.pixel_count();
  const SampleRound& round = output.round();
  std::uint64_t done = 0;
  while (done < total) {
    const auto n = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(pixels_per_wave(round.count), total - done));
    const std::size_t mark = profiler_.wave_mark();
    const WaveArgs wave{rect.x,      rect.y,      rect.width,  static_cast<std::uint32_t>(done),
                        round.first, round.count, n * round.count};
    if (trace(wave)) {
      profiler_.commit_wave();
      ++counted_.waves;
      resolver_.resolve(launcher_, output, n, first + done);
      profiler_.settle();
      done += n;
      continue;
    }
    profiler_.drop_wave(mark);
    if (n == 1)
      throw DeviceError("the ray tree of one pixel does not fit in a queue of " +
                        std::to_string(capacity_) +
                        " rays: raise --wavefront or lower the maximum depth");
    // Each sample is independent, so fewer pixels per wave give the same bits.
    wave_rays_ = std::max<std::uint32_t>(1, n / 2) * round.count;
    ++counted_.wave_restarts;
  }
}

void WaveLoop::harvest(RenderStats& stats) {
  RenderStats own = counted_;
  profiler_.harvest(own);
  counted_ = RenderStats{};
  stats.merge(own);
}

std::uint64_t WaveLoop::device_bytes() const { return own_bytes() + resolver_.bytes(); }

}  // namespace clrt
