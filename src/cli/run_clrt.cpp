#include "cli/run_clrt.hpp"

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "device/background_store.hpp"
#include "device/device_select.hpp"
#include "geometry/geometry_data.hpp"
#include "image/fsf_animation.hpp"
#include "cli/dark_scene_note.hpp"
#include "cli/image_write_options.hpp"
#include "cli/out_of_memory.hpp"
#include "cli/picture_options.hpp"
#include "cli/preview_window.hpp"
#include "cli/resume_plan.hpp"
#include "cli/scene_dump.hpp"
#include "image/interrupt_cleanup.hpp"
#include "image/output_target.hpp"
#include "render/frame_setup.hpp"
#include "render/orbit.hpp"
#include "render/output_guard.hpp"
#include "render/render_limits.hpp"
#include "render/device_preparation.hpp"
#include "render/renderer.hpp"
#include "render/usage_error.hpp"
#include "scene/scene.hpp"
#include "version.hpp"

namespace clrt {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string seconds_text(double seconds) {
  std::ostringstream text;
  text.precision(2);
  text << std::fixed << seconds << " s";
  return text.str();
}

// Where frame `frame` goes: the output itself for a still or an FSF animation, else a numbered
// file beside it.
ImageOutput frame_output(const ImageOutput& output, const FramePlan& frames, std::uint32_t frame) {
  if (!frames.animated || output.format == ImageFormat::Fsf) return output;
  return {numbered_frame_path(output.path, frame, frames.frames), output.format};
}

}  // namespace

ImageOutput resolve_image_output(const CliOptions& cli, const FramePlan& frames) {
  ImageOutput output;
  try {
    if (cli.no_write) return {"", cli.format.value_or(ImageFormat::Png)};
    output = resolve_output(output_path(cli), cli.format);
    check_picture_output(cli, output);
    if (output.is_stdout()) {
      if (frames.count() > 1 && output.format != ImageFormat::Fsf)
        throw UsageError("several frames go to standard output only as FSF (--format fsf)");
      return output;
    }
    check_output_writable(frame_output(output, frames, frames.first).path);
  } catch (const ImageError& e) {
    throw UsageError(e.what());
  }
  return output;
}

void check_output_space(const ImageOutput& output, const FramePlan& frames,
                        const PixelRect& region) {
  if (writes_nothing(output) || output.is_stdout() || find_output_target(output.path).stream)
    return;
  const bool one_file = !frames.animated || output.format == ImageFormat::Fsf;
  const std::uint64_t file_bytes =
      (one_file ? frames.count() : 1) * minimum_file_bytes(output.format, region.pixel_count());
  if (file_bytes == 0) return;
  // The first file is written beside the one it replaces; numbered frames that replace an
  // earlier animation's free their space as they go.
  std::uint64_t needed = file_bytes;
  if (!one_file) {
    std::uint64_t replaced = 0;
    for (std::uint32_t frame = frames.first; frame <= frames.last; ++frame) {
      std::error_code absent;
      const std::uintmax_t size =
          std::filesystem::file_size(frame_output(output, frames, frame).path, absent);
      if (!absent) replaced += size;
    }
    const std::uint64_t all = frames.count() * file_bytes;
    needed = std::max(file_bytes, all > replaced ? all - replaced : 0);
  }
  const std::uint64_t free = free_bytes_for(output.path);
  if (needed > free)
    throw RenderLimitError(1, "cannot write " + output.path + ": it needs at least " +
                                  std::to_string(needed) + " bytes and its file system has " +
                                  std::to_string(free) + " free");
}

namespace {

std::string describe_written(const ImageOutput& output, const FramePlan& frames) {
  if (writes_nothing(output))
    return "rendered " +
           (frames.animated ? std::to_string(frames.count()) + " frames" : "the image") +
           ", wrote nothing (--no-write)";
  const std::string where = output.is_stdout() ? "standard output" : output.path;
  if (!frames.animated) return "wrote " + where;
  const std::string count = std::to_string(frames.count()) + " frames";
  if (output.format == ImageFormat::Fsf) return "wrote " + count + " to " + where;
  return "wrote " + count + " as " + frame_output(output, frames, frames.first).path + "...";
}

void print_stats(const CliOptions& cli, const RenderStats& stats, const ImageOutput& output) {
  // Standard output may carry the image itself.
  std::ostream& out = output.is_stdout() ? std::cerr : std::cout;
  if (cli.stats == StatsFormat::Text) out << stats.to_text();
  if (cli.stats == StatsFormat::Json) out << stats.to_json().dump(2) << "\n";
}

// The devices and their programs, prepared while the scene loads.
struct Devices {
  std::vector<DeviceEntry> entries;
  std::vector<PreparedDevice> prepared;
  double seconds = 0;
};

// --preview's window, or a warning and nothing: the render goes on without it.
std::unique_ptr<PreviewWindow> open_preview(const PixelRect& region,
                                            const DisplayTransform& display, Progress& progress) {
  std::string why;
  std::unique_ptr<PreviewWindow> window =
      PreviewWindow::open(region.width, region.height, display, why);
  if (!window) progress.message("clrt: warning: --preview: " + why + "; rendering without it");
  return window;
}

int render_frames(const CliOptions& cli, Scene& scene, const FramePlan& frames,
                  const ImageOutput& output, RenderStats& stats, Progress& progress,
                  Devices& devices, Clock::time_point start) {
  const RenderSetup setup = checked_render_setup(cli, scene, devices.entries);
  if (!cli.quiet) {
    for (const DeviceEntry& d : setup.devices) progress.message(device_line(d));
    if (const auto note = dark_scene_note(scene, setup.options.mode))
      progress.message("clrt: note: " + cli.scene + ": " + *note);
  }
  const PixelRect region = render_region(setup.options);
  check_output_space(output, frames, region);
  ResumePlan resume(cli, output, frames, scene, setup.options);
  if (!cli.quiet && !resume.resumed_text().empty())
    progress.message("clrt: " + resume.resumed_text());
  const DisplayTransform display = display_transform(cli, setup.options.mode);
  const std::unique_ptr<PreviewWindow> preview =
      cli.preview ? open_preview(region, display, progress) : nullptr;
  Renderer renderer(scene, built_geometry(scene, progress), setup, std::move(devices.prepared),
                    &progress);
  // With a transform beyond the contract's quantisation the writer needs the floats.
  const bool eight_bit = renders_bytes(output, display);
  std::unique_ptr<FsfAnimationWriter> animation;
  if (frames.animated && output.format == ImageFormat::Fsf && !writes_nothing(output))
    animation = std::make_unique<FsfAnimationWriter>(output, static_cast<int>(region.width),
                                                     static_cast<int>(region.height),
                                                     frames.count(), display);
  const std::string size = std::to_string(region.width) + "x" + std::to_string(region.height);
  if (frames.animated) progress.frames(frames.last - resume.first_frame() + 1);
  for (std::uint32_t frame = resume.first_frame(); frame <= frames.last; ++frame) {
    if (frames.animated)
      renderer.set_camera(make_camera(
          orbit_camera(scene.camera, frames.orbit_degrees, frame - 1, frames.frames), setup.options));
    progress.start(frames.animated ? "frame " + std::to_string(frame) + "/" +
                                         std::to_string(frames.frames)
                                   : "rendering",
                   renderer.render_work(region));
    ResumableRender resumable = resume.start(frame);
    accept_stop_requests(resume.keeps_work());
    const AnyImage image =
        renderer.render(region, eight_bit, &progress, preview.get(),
                        resume.keeps_work() ? &resumable : nullptr);
    accept_stop_requests(false);
    progress.phase("writing");
    const auto write_start = Clock::now();
    WriteOptions write_options = image_write_options(cli.exr_pixel, display, "clrt");
    write_options.samples = resume.samples_note(resumable);
    std::visit(
        [&](const auto& pixels) {
          if (animation)
            animation->add_frame(pixels);
          else if (!writes_nothing(output))
            write_image(frame_output(output, frames, frame), pixels, write_options);
        },
        image);
    stats.write_seconds += seconds_since(write_start);
    if (const auto stopped =
            resume.finish_frame(frame, resumable, frame_output(output, frames, frame).path)) {
      progress.finish(*stopped);
      end_by_stop_request();
    }
    if (frames.animated && !animation && !writes_nothing(output))
      progress.log("clrt: wrote " + frame_output(output, frames, frame).path + " (" + size + ", " +
                   seconds_text(seconds_since(start)) + ")");
  }
  if (animation) animation->finish();
  if (preview && preview->bands_dropped() > 0)
    progress.message("clrt: warning: --preview: clrt-view fell behind; " +
                     std::to_string(preview->bands_dropped()) +
                     " bands were not shown (the image written is whole)");
  renderer.report(stats);
  stats.build_seconds += devices.seconds;
  stats.width = region.width;
  stats.height = region.height;
  stats.frames = frames.count();
  stats.total_seconds = seconds_since(start);
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  stats.peak_host_bytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
  progress.finish("clrt: " + describe_written(output, frames) + " (" + size + ", " +
                  seconds_text(stats.total_seconds) + ")");
  print_stats(cli, stats, output);
  start_background_stores();
  return 0;
}

}  // namespace

RenderSetup checked_render_setup(const CliOptions& cli, const Scene& scene,
                                 std::vector<DeviceEntry> devices) {
  RenderSetup setup;
  setup.options = resolve_render_options(cli, scene);
  setup.devices = std::move(devices);
  setup.profile = cli.stats != StatsFormat::None;
  check_render_setup(setup);
  check_render_limits(scene, setup.options, measure_budget(setup.devices, setup.options));
  return setup;
}

GeometryData built_geometry(Scene& scene, Progress& progress) {
  progress.phase("building the BVH");
  // The BVH's tables hold all the device needs: the meshes are freed as the build goes.
  GeometryData geometry = build_geometry_for_render(scene);
  // The loader's and the builder's scratch goes back to the system before the devices and the
  // image take their memory, rather than staying in the heap's free lists.
  malloc_trim(0);
  return geometry;
}

void check_outputs_are_not_inputs(const ImageOutput& output, const FramePlan& frames,
                                  const Scene& scene) {
  try {
    if (!output.is_stdout() && !writes_nothing(output))
      for (std::uint32_t frame = frames.first; frame <= frames.last; ++frame)
        check_output_is_not_input(frame_output(output, frames, frame).path, scene);
  } catch (const ImageError& e) {
    throw UsageError(e.what());
  }
}

int run_clrt(const CliOptions& cli) {
  const auto start = Clock::now();
  // The CPU drivers read their thread counts when the first OpenCL call loads them, before any
  // device can be asked which it is: PoCL, and Intel's CPU runtime. Others ignore both.
  if (cli.threads) {
    setenv("POCL_MAX_PTHREAD_COUNT", std::to_string(*cli.threads).c_str(), 1);
    setenv("DPCPP_CPU_NUM_CUS", std::to_string(*cli.threads).c_str(), 1);
  }
  if (cli.dump_scene) return dump_scene(cli);
  if (cli.list_devices) {
    std::cout << device_table(enumerate_devices());
    return 0;
  }
  const FramePlan frames = resolve_frames(cli.animation);
  const ImageOutput output = resolve_image_output(cli, frames);
  Progress progress(!cli.quiet);
  RenderStats stats;
  stats.scene = cli.scene;
  stats.version = clrt_version_string();
  progress.phase("loading " + cli.scene);
  // The scene loads on a thread of its own while this one starts OpenCL and builds the kernels
  // (LLVM, inside PoCL, keeps per-thread state: it stays on the main thread).
  std::future<Scene> loading = std::async(std::launch::async, [&cli, &stats, start] {
    Scene loaded = naming_out_of_memory("loading " + cli.scene, [&] { return load_scene(cli.scene); });
    stats.load_seconds = seconds_since(start);
    return loaded;
  });
  Devices devices;
  std::exception_ptr device_error;
  try {
    const auto prepare_start = Clock::now();
    naming_out_of_memory("starting the devices", [&] {
      devices.entries = select_devices(cli.device);
      devices.prepared = prepare_devices(devices.entries, cli.mode.value_or(RenderOptions{}.mode), [&](bool first_run) {
        progress.phase(first_run ? "building kernels (first run on this device)" : "building kernels");
      });
    });
    if (loading.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
      progress.phase("loading " + cli.scene);
    devices.seconds = seconds_since(prepare_start);
  } catch (...) {
    device_error = std::current_exception();
  }
  Scene scene;
  try {
    scene = loading.get();
  } catch (const SceneError& e) {
    // A scene error is the user's to fix first, whatever else went wrong.
    progress.finish();
    std::cerr << e.what() << "\n";
    return 2;
  }
  if (device_error) std::rethrow_exception(device_error);
  check_outputs_are_not_inputs(output, frames, scene);
  if (!cli.quiet)
    for (const std::string& warning : scene.warnings) progress.message(warning);
  // An empty scene is a valid one (a background, a test of the camera), but more often a scene
  // whose objects went missing: rendered, with a word.
  if (!cli.quiet && scene.instances.empty() && scene.triangles.empty())
    progress.message("clrt: warning: " + cli.scene + " has no objects: the image is its background");
  return naming_out_of_memory("building the scene's geometry or rendering", [&] {
    return render_frames(cli, scene, frames, output, stats, progress, devices, start);
  });
}

}  // namespace clrt
