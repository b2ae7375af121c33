// An integrator renders rectangles of the image on one device. Each is a host file (its class,
// derived from WaveLoop, and its IntegratorEntry) and a device file, listed once in
// integrator_table(): the command line, the checks before a render, the experiment runner, the
// renderer and the device's program all read that table. The first row is the product; every
// integrator gives the same bits (kernels/accumulate.cl says why).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device/device_profile.hpp"
#include "device/kernel_args.hpp"
#include "render/busy_timeline.hpp"
#include "render/device_buffer.hpp"
#include "render/device_frame.hpp"
#include "render/integrator_names.hpp"
#include "render/pixel_rect.hpp"
#include "render/render_options.hpp"
#include "render/render_stats.hpp"
#include "render/sample_rounds.hpp"
#include "render/wave_sizes.hpp"

namespace clrt {

struct IntegratorConfig {
  std::uint32_t capacity = 0;      // camera samples per wave, and rays per queue where it queues
  std::size_t local_size = 64;
  DeviceClass device_class = DeviceClass::Cpu;  // the class the device's program was built for
  bool profile = false;            // per-kernel device times and rays by kind (--stats)
  bool shade_by_class = false;     // RenderOptions::shade_by_class
  BusyTimeline* timeline = nullptr;  // the device's, shared by its lanes (profiling only)
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Renders `output`'s round of samples of `rect`, its pixels in row-major order, into
  // `output` from its pixel `first` on.
  virtual void render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) = 0;
  // Pixels one wave takes with `samples` samples each: a good size for a piece of work.
  virtual std::uint32_t pixels_per_wave(std::uint32_t samples) const = 0;
  // Waits for the device and adds what was rendered since the last call to `stats`.
  virtual void harvest(RenderStats& stats) = 0;
  // Its own buffers on the device (the frame's are counted once by the caller).
  virtual std::uint64_t device_bytes() const = 0;
};

struct IntegratorEntry {
  const char* name;     // as --integrator takes it, and RenderOptions::integrator holds it
  const char* summary;  // one line for --help
  // What it adds to the options of the program of a device of `device_class`. A device builds
  // one program for every scene and integrator, with every row's options (renderer_program.hpp).
  std::string (*program_options)(DeviceClass device_class);
  // Throws UsageError when a render of `options` cannot run with it on a device of `profile`
  // (with the command line's overrides): called before any work.
  void (*check)(const RenderOptions& options, const DeviceProfile& profile);
  // The buffers one lane of it allocates for waves of `sizes`, each as the allocation names it:
  // the checks before a render hold these against the device's limits.
  std::vector<DeviceBuffer> (*buffers)(const WaveSizes& sizes);
  std::unique_ptr<Integrator> (*make)(DeviceContext& device, const compute::program& program,
                                      const DeviceFrame& frame, const IntegratorConfig& config);
  // Every way the kernels it launches differ in `program` from the argument structures it binds
  // them with (empty when they agree): tests/kernels/test_bindings.cpp runs it for every row, so
  // an integrator's structures may live in its own file.
  std::vector<std::string> (*binding_mismatches)(const compute::program& program);
};

// An entry's `binding_mismatches` for an integrator that launches kernels through Args...
template <class... Args>
std::vector<std::string> kernel_binding_mismatches(const compute::program& program) {
  std::vector<std::string> out;
  (
      [&] {
        const compute::kernel kernel(program, Args::kName);
        for (std::string& line : signature_mismatches(kernel, expected_args(Args{})))
          out.push_back(std::move(line));
      }(),
      ...);
  return out;
}

// An entry's `make` for the integrator class T.
template <class T>
std::unique_ptr<Integrator> make_integrator(DeviceContext& device, const compute::program& program,
                                            const DeviceFrame& frame,
                                            const IntegratorConfig& config) {
  return std::make_unique<T>(device, program, frame, config);
}

// Every integrator, the product first.
const std::vector<IntegratorEntry>& integrator_table();
const IntegratorEntry& integrator_entry(const std::string& name);
// Every row's program options for a device of `device_class`, joined.
std::string integrator_program_options(DeviceClass device_class);

}  // namespace clrt
