#include "render/wave_resolver.hpp"

#include "device/transfer.hpp"

namespace clrt {

WaveResolver::WaveResolver(DeviceContext& device, const compute::program& program,
                           std::uint32_t max_samples, std::uint32_t max_pixels)
    : device_(device),
      sample_colour_(allocate<dev::f4>(device, max_samples, "sample colour")),
      pixels_(allocate<dev::f4>(device, max_pixels, "pixel")),
      max_samples_(max_samples),
      max_pixels_(max_pixels),
      resolve_(program),
      host_pixels_(max_pixels) {}

void WaveResolver::clear(std::uint32_t samples) {
  const dev::f4 zero{0, 0, 0, 0};
  device_.queue().enqueue_fill_buffer(sample_colour_.buffer, &zero, sizeof zero, 0,
                                      sizeof zero * samples);
}

void WaveResolver::resolve(Profiler& profiler, std::uint32_t samples_per_pixel,
                           std::uint32_t pixel_count, PixelStore& store, std::uint64_t first) {
  profiler.launch(resolve_, {sample_colour_, samples_per_pixel, pixel_count, pixels_},
                  pixel_count, 0);
  device_.queue().enqueue_read_buffer(pixels_.buffer, 0, sizeof(dev::f4) * pixel_count,
                                      host_pixels_.data());
  store.store(first, pixel_count, host_pixels_.data());
}

std::uint64_t WaveResolver::bytes() const {
  return sizeof(dev::f4) * (std::uint64_t{max_samples_} + max_pixels_);
}

}  // namespace clrt
