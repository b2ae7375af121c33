#include "render/wave_resolver.hpp"

#include "device/transfer.hpp"

namespace clrt {

std::vector<DeviceBuffer> WaveResolver::buffers(std::uint64_t samples, std::uint64_t pixels) {
  return {CLRT_WAVE_RESOLVER_BUFFERS(CLRT_BUFFER_DESCRIBE)};
}

WaveResolver::WaveResolver(DeviceContext& device, const compute::program& program,
                           std::uint32_t samples, std::uint32_t pixels, float max_sample_value)
    : device_(device), max_sample_value_(max_sample_value), resolve_(program), host_pixels_(pixels) {
  CLRT_WAVE_RESOLVER_BUFFERS(CLRT_BUFFER_ALLOCATE)
  for (const DeviceBuffer& b : buffers(samples, pixels)) bytes_ += b.bytes;
}

void WaveResolver::clear(std::uint32_t samples) {
  const dev::f4 zero{0, 0, 0, 0};
  device_.queue().enqueue_fill_buffer(sample_colour_.buffer, &zero, sizeof zero, 0,
                                      sizeof zero * samples);
}

void WaveResolver::resolve(Launcher& launcher, RoundOutput& output, std::uint32_t pixel_count,
                           std::uint64_t first) {
  const SampleRound& round = output.round();
  if (round.first > 0)
    device_.queue().enqueue_write_buffer(pixels_.buffer, 0, sizeof(dev::f4) * pixel_count,
                                         output.sums_before(first));
  launcher.launch(resolve_,
                  {sample_colour_, round.count, round.first, pixel_count, max_sample_value_, pixels_},
                  pixel_count, 0);
  device_.queue().enqueue_read_buffer(pixels_.buffer, 0, sizeof(dev::f4) * pixel_count,
                                      host_pixels_.data());
  output.take(first, pixel_count, host_pixels_.data());
}

}  // namespace clrt
