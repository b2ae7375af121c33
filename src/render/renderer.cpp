#include "render/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "device/kernel_source.hpp"
#include "geometry/geometry_data.hpp"
#include "render/frame_setup.hpp"
#include "render/progress.hpp"
#include "render/wavefront.hpp"

namespace clrt {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct DeviceWorker {
  std::unique_ptr<DeviceContext> context;
  std::unique_ptr<WavefrontRenderer> renderer;
};

// Pixel ranges are claimed one at a time from a shared counter, each device a wave's worth:
// a faster device takes more. Every pixel's colour depends only on the pixel, so the split
// never changes the image.
class PixelDealer {
 public:
  explicit PixelDealer(std::uint32_t total) : total_(total) {}
  bool next(std::uint32_t block, std::uint32_t& first, std::uint32_t& count) {
    first = next_.fetch_add(block);
    if (first >= total_) return false;
    count = std::min(block, total_ - first);
    return true;
  }

 private:
  std::uint32_t total_;
  std::atomic<std::uint32_t> next_{0};
};

}  // namespace

FloatImage render(const Scene& scene, const RenderSetup& setup, RenderStats& stats) {
  const RenderOptions& options = setup.options;
  auto start = Clock::now();
  const GeometryData geometry = build_geometry(scene);
  stats.bvh_seconds = geometry.build_seconds;
  stats.geometry_bytes = geometry.device_bytes();
  stats.bvh_bytes = geometry.nodes.size() * sizeof(dev::BvhNode);
  const FrameData frame = make_frame(scene, options);

  start = Clock::now();
  const std::string source = renderer_program_source();
  std::vector<DeviceWorker> workers;
  for (const DeviceEntry& entry : setup.devices) {
    DeviceWorker w;
    w.context = std::make_unique<DeviceContext>(entry);
    const compute::program program = w.context->build(source);
    const std::uint32_t wavefront =
        options.wavefront ? options.wavefront : default_wavefront(entry.device);
    w.renderer = std::make_unique<WavefrontRenderer>(*w.context, program, frame, geometry,
                                                     wavefront, setup.profile);
    workers.push_back(std::move(w));
  }
  stats.build_seconds = seconds_since(start);

  start = Clock::now();
  FloatImage image;
  image.width = options.width;
  image.height = options.height;
  const auto pixels = static_cast<std::uint32_t>(image.width) * static_cast<std::uint32_t>(image.height);
  image.rgb.assign(3 * std::size_t{pixels}, 0.0f);
  PixelDealer dealer(pixels);
  Progress progress(pixels, setup.progress);
  std::vector<std::exception_ptr> errors(workers.size());
  const auto work = [&](std::size_t i) {
    try {
      std::uint32_t first = 0, count = 0;
      WavefrontRenderer& renderer = *workers[i].renderer;
      while (dealer.next(renderer.pixels_per_wave(), first, count)) {
        renderer.render(first, count, image.rgb.data() + 3 * std::size_t{first});
        progress.advance(count);
      }
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  if (workers.size() == 1) {
    work(0);
  } else {
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < workers.size(); ++i) threads.emplace_back(work, i);
    for (auto& t : threads) t.join();
  }
  progress.finish();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  stats.render_seconds = seconds_since(start);
  for (const DeviceWorker& w : workers) stats.merge(w.renderer->stats());
  return image;
}

}  // namespace clrt
