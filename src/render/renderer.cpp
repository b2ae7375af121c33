#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "device/device_profile.hpp"
#include "geometry/geometry_data.hpp"
#include "render/frame_setup.hpp"
#include "render/integrator.hpp"
#include "render/progress.hpp"
#include "render/render_tuning.hpp"
#include "render/renderer_program.hpp"
#include "render/usage_error.hpp"

namespace clrt {

// Renderer::Devices holds these, so they cannot live in the anonymous namespace.
// One wave in flight: its own command queue and integrator (with its own queues).
struct Lane {
  std::unique_ptr<DeviceContext> context;
  std::unique_ptr<Integrator> integrator;
};

// One device: the frame every lane reads, and the lanes. The program is held for as long as its
// kernels run: the specification says kernels keep it alive, but Intel's CPU runtime rendered
// black images when only the kernels did (before buffers were zero-filled when allocated, the
// workaround in docs/devices.md; not tried without since).
struct DeviceWorker {
  std::unique_ptr<DeviceContext> context;
  compute::program program;
  std::unique_ptr<DeviceFrame> frame;
  std::vector<Lane> lanes;
  std::unique_ptr<BusyTimeline> timeline;
  DeviceReport report;
  std::uint64_t camera_samples = 0;  // traced since the last report: its share of the work
};

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

DeviceReport report_of(const DeviceEntry& entry, const DeviceProfile& tuning) {
  const compute::device& d = entry.device;
  DeviceReport r;
  r.platform = d.platform().name();
  r.name = d.name();
  r.driver = d.driver_version();
  r.opencl_c = d.get_info<std::string>(CL_DEVICE_OPENCL_C_VERSION);
  r.device_class = class_name(tuning.device_class);
  r.local_size = tuning.local_size;
  r.wavefront = tuning.wavefront;
  r.lanes = tuning.lanes;
  return r;
}

// Bands of whole rows of the region are claimed one at a time, each about a wave's worth of
// pixels for the device that claims it: a faster device takes more. Every pixel's colour
// depends only on the pixel, so the split never changes the image.
class RowDealer {
 public:
  explicit RowDealer(const PixelRect& region) : region_(region) {}

  bool next(std::uint32_t wave_pixels, PixelRect& band) {
    const std::uint32_t rows = std::max<std::uint32_t>(1, wave_pixels / region_.width);
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_ || next_row_ >= region_.height) return false;
    band = region_;
    band.y = region_.y + next_row_;
    band.height = std::min(rows, region_.height - next_row_);
    next_row_ += band.height;
    return true;
  }

  // After a lane fails, the others finish their band and take no more.
  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
  }

 private:
  PixelRect region_;
  std::uint32_t next_row_ = 0;
  bool stopped_ = false;
  std::mutex mutex_;
};

// Every lane's failure, not only the first: one alone (or the same one on every lane) is
// rethrown as it is, different ones become one DeviceError listing each.
void rethrow_lane_errors(const std::vector<std::exception_ptr>& errors) {
  std::exception_ptr first;
  std::vector<std::string> messages;
  for (const std::exception_ptr& e : errors) {
    if (!e) continue;
    if (!first) first = e;
    try {
      std::rethrow_exception(e);
    } catch (const std::exception& ex) {
      if (std::find(messages.begin(), messages.end(), ex.what()) == messages.end())
        messages.emplace_back(ex.what());
    } catch (...) {
      messages.emplace_back("an unknown failure");
    }
  }
  if (!first) return;
  if (messages.size() == 1) std::rethrow_exception(first);
  std::string all = "the devices failed in " + std::to_string(messages.size()) + " ways:";
  for (const std::string& m : messages) all += "\n  " + m;
  throw DeviceError(all);
}

// One round over `region`: its rows dealt out among the lanes, a thread each, all joined
// before the next round adds to the sums this one leaves. Adds each lane's camera samples to
// `traced`.
void render_round(const PixelRect& region, RoundOutput& output,
                  const std::vector<Integrator*>& workers, std::vector<std::uint64_t>& traced,
                  Progress* progress) {
  RowDealer dealer(region);
  std::vector<std::exception_ptr> errors(workers.size());
  const std::uint32_t samples = output.round().count;
  const auto work = [&](std::size_t i) {
    try {
      Integrator& integrator = *workers[i];
      PixelRect band;
      while (dealer.next(integrator.pixels_per_wave(samples), band)) {
        const std::uint64_t offset = std::uint64_t{band.y - region.y} * region.width;
        integrator.render(band, output, offset);
        traced[i] += band.pixel_count() * samples;
        if (progress) progress->advance(band.pixel_count() * samples);
      }
    } catch (...) {
      errors[i] = std::current_exception();
      dealer.stop();
    }
  };
  if (workers.size() == 1) {
    work(0);
  } else {
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < workers.size(); ++i) threads.emplace_back(work, i);
    for (auto& t : threads) t.join();
  }
  rethrow_lane_errors(errors);
}

}  // namespace

PixelRect render_region(const RenderOptions& options) {
  return options.region.value_or(PixelRect{0, 0, static_cast<std::uint32_t>(options.width),
                                           static_cast<std::uint32_t>(options.height)});
}

void check_render_setup(const RenderSetup& setup) {
  const PixelRect region = render_region(setup.options);
  const std::uint64_t width = static_cast<std::uint64_t>(setup.options.width);
  const std::uint64_t height = static_cast<std::uint64_t>(setup.options.height);
  if (region.pixel_count() == 0 || region.x + std::uint64_t{region.width} > width ||
      region.y + std::uint64_t{region.height} > height)
    throw UsageError("the region " + describe(region) + " is not a non-empty part of the " +
                     std::to_string(width) + "x" + std::to_string(height) + " image");
  const IntegratorEntry& integrator = integrator_entry(setup.options.integrator);
  for (const DeviceEntry& entry : setup.devices)
    integrator.check(setup.options, render_tuning(entry.device, setup.options));
}

struct Renderer::Devices {
  std::vector<DeviceWorker> workers;
};

namespace {

GeometryData checked_geometry(const Scene& scene, const RenderSetup& setup, Progress* progress) {
  check_render_setup(setup);
  if (progress) progress->phase("building the BVH");
  return build_geometry(scene);
}

}  // namespace

Renderer::Renderer(const Scene& scene, const RenderSetup& setup, Progress* progress)
    : Renderer(scene, checked_geometry(scene, setup, progress), setup, progress) {}

Renderer::Renderer(const Scene& scene, GeometryData geometry, const RenderSetup& setup,
                   Progress* progress)
    : Renderer(scene, std::move(geometry), setup, {}, progress) {}

Renderer::Renderer(const Scene& scene, GeometryData geometry, const RenderSetup& setup,
                   std::vector<PreparedDevice> prepared, Progress* progress)
    : options_(setup.options), devices_(std::make_unique<Devices>()) {
  check_render_setup(setup);
  // Shared by every device's frame: a device that reads the tables in place holds them until its
  // runtime has deleted its buffers, which may be after this renderer is gone.
  const auto tables = std::make_shared<const GeometryData>(std::move(geometry));
  setup_stats_.bvh_seconds = tables->build_seconds;
  setup_stats_.geometry_bytes = tables->device_bytes();
  setup_stats_.bvh_bytes = tables->nodes.size() * sizeof(dev::BvhNode);
  const FrameData frame = make_frame(scene, *tables, options_);
  const SceneFeatures features{!tables->motions.empty(), has_textures(*frame.textures)};

  if (progress) progress->phase("building the kernels");
  const auto start = Clock::now();
  for (std::size_t i = 0; i < setup.devices.size(); ++i) {
    const DeviceEntry& entry = setup.devices[i];
    const DeviceProfile tuning = render_tuning(entry.device, options_);
    DeviceWorker w;
    if (i < prepared.size()) {
      w.context = std::move(prepared[i].context);
      // A program prepared for another mode holds another transport model.
      w.program = prepared[i].mode == options_.mode && prepared[i].features == features
                      ? prepared[i].program
                      : build_renderer_program(*w.context, options_.mode, features);
    } else {
      w.context = std::make_unique<DeviceContext>(entry);
      w.program = build_renderer_program(*w.context, options_.mode, features);
    }
    w.frame = std::make_unique<DeviceFrame>(*w.context, frame, tables);
    w.timeline = std::make_unique<BusyTimeline>();
    IntegratorConfig config;
    config.capacity = tuning.wavefront;
    config.local_size = tuning.local_size;
    config.device_class = tuning.device_class;
    config.profile = setup.profile;
    config.shade_by_class = options_.shade_by_class;
    config.timeline = w.timeline.get();
    for (std::uint32_t k = 0; k < tuning.lanes; ++k) {
      Lane lane;
      lane.context = std::make_unique<DeviceContext>(w.context->lane());
      lane.integrator = integrator_entry(options_.integrator)
                            .make(*lane.context, w.program, *w.frame, config);
      w.lanes.push_back(std::move(lane));
    }
    rays_in_flight_ += std::uint64_t{tuning.wavefront} * tuning.lanes;
    w.report = report_of(entry, tuning);
    devices_->workers.push_back(std::move(w));
  }
  setup_stats_.build_seconds = seconds_since(start);
  setup_stats_.integrator = integrator_entry(options_.integrator).name;
  setup_stats_.samples_per_pixel = static_cast<std::uint64_t>(options_.samples);
}

Renderer::~Renderer() = default;

AnyImage Renderer::render(const PixelRect& region, bool eight_bit, Progress* progress,
                          PixelStore* watcher, ResumableRender* resumable) {
  const auto start = Clock::now();
  std::optional<Placement> placement;
  if (region.width != static_cast<std::uint32_t>(options_.width) ||
      region.height != static_cast<std::uint32_t>(options_.height))
    placement = Placement{static_cast<int>(region.x), static_cast<int>(region.y), options_.width,
                          options_.height};
  const int width = static_cast<int>(region.width), height = static_cast<int>(region.height);
  AnyImage image;
  std::unique_ptr<PixelStore> store;
  if (eight_bit) {
    Rgba8Image& bytes = image.emplace<Rgba8Image>(
        width, height, std::vector<std::vector<std::uint8_t>>(1), placement);
    bytes.frames[0].resize(4 * region.pixel_count());
    store = std::make_unique<BytePixelStore>(bytes);
  } else {
    FloatImage& floats = image.emplace<FloatImage>(
        width, height, std::vector<float>(3 * region.pixel_count()), placement);
    store = std::make_unique<FloatPixelStore>(floats);
  }
  std::vector<Integrator*> workers;
  std::vector<DeviceWorker*> owners;  // each lane's device
  for (DeviceWorker& d : devices_->workers)
    for (Lane& lane : d.lanes) {
      workers.push_back(lane.integrator.get());
      owners.push_back(&d);
    }
  std::vector<std::uint64_t> traced(workers.size(), 0);
  const auto total = static_cast<std::uint32_t>(options_.samples);
  const std::uint32_t taken_before = resumable ? resumable->samples : 0;
  const std::vector<SampleRound> rounds =
      sample_rounds(total, region.pixel_count(), rays_in_flight_, taken_before);
  std::vector<dev::f4> sums;
  if (resumable && taken_before > 0)
    sums = std::move(resumable->sums);
  else if (rounds.size() > 1 || (resumable && resumable->keep_finished_sums))
    sums.resize(region.pixel_count());
  if (progress && taken_before > 0) progress->advance(region.pixel_count() * taken_before);
  sample_rounds_ = std::max<std::uint64_t>(sample_rounds_, rounds.size());
  std::uint32_t taken = taken_before;
  for (std::size_t r = 0; r < rounds.size(); ++r) {
    const SampleRound& round = rounds[r];
    RoundOutput output(round, sums, *store, watcher, resumable && resumable->keep_finished_sums);
    render_round(region, output, workers, traced, progress);
    taken = round.first + round.count;
    if (progress && rounds.size() > 1)
      progress->note(std::to_string(taken) + "/" + std::to_string(round.total) + " spp");
    if (resumable && resumable->stop && resumable->stop(static_cast<std::uint32_t>(r + 1)))
      break;
  }
  // Stopped early, or resumed with every sample taken: no last round stored the mean.
  if (taken < total || rounds.empty()) {
    const std::vector<dev::f4> mean = mean_of_sums(sums.data(), region.pixel_count(), taken);
    store->store(0, static_cast<std::uint32_t>(region.pixel_count()), mean.data());
  }
  if (resumable) {
    resumable->samples = taken;
    resumable->sums = std::move(sums);
  }
  for (std::size_t i = 0; i < workers.size(); ++i) owners[i]->camera_samples += traced[i];
  render_seconds_ += seconds_since(start);
  return image;
}

std::uint64_t Renderer::render_work(const PixelRect& region) const {
  return region.pixel_count() * static_cast<std::uint64_t>(options_.samples);
}

void Renderer::set_camera(const dev::Camera& camera) {
  for (DeviceWorker& w : devices_->workers) w.frame->set_camera(*w.context, camera);
}

void Renderer::report(RenderStats& stats) {
  const auto start = Clock::now();
  RenderStats own;
  own.sample_rounds = sample_rounds_;
  sample_rounds_ = 0;
  for (DeviceWorker& w : devices_->workers) {
    own.device_bytes += w.frame->bytes;
    for (Lane& lane : w.lanes) {
      lane.integrator->harvest(own);
      own.device_bytes += lane.integrator->device_bytes();
    }
    own.devices.push_back(w.report);
    const DeviceTime time = w.timeline->take();
    own.devices.back().busy_seconds = time.busy_seconds;
    own.devices.back().camera_samples = w.camera_samples;
    w.camera_samples = 0;
    for (const auto& [name, seconds] : time.kernel_share_seconds) own.kernels[name].share_seconds += seconds;
  }
  stats.merge(own);
  stats.render_seconds += render_seconds_ + seconds_since(start);
  stats.bvh_seconds = setup_stats_.bvh_seconds;
  stats.build_seconds = setup_stats_.build_seconds;
  stats.geometry_bytes = setup_stats_.geometry_bytes;
  stats.bvh_bytes = setup_stats_.bvh_bytes;
  stats.integrator = setup_stats_.integrator;
  stats.samples_per_pixel = setup_stats_.samples_per_pixel;
  render_seconds_ = 0;
}

FloatImage render(const Scene& scene, const RenderSetup& setup, RenderStats& stats) {
  Renderer renderer(scene, setup);
  const PixelRect region = render_region(setup.options);
  Progress progress(setup.progress);
  progress.start("rendering", renderer.render_work(region));
  FloatImage image = std::get<FloatImage>(renderer.render(region, false, &progress));
  progress.finish();
  renderer.report(stats);
  stats.width = region.width;
  stats.height = region.height;
  return image;
}

}  // namespace clrt
