// The megakernel integrator on one device: one launch per wave, each work-item a camera sample
// walking its whole ray tree (kernels/megakernel.cl); the waves and their end are WaveLoop's. It
// keeps no queues, so its memory is a colour and a count per camera sample of a wave.
#include <string>

#include "device/transfer.hpp"
#include "render/usage_error.hpp"
#include "render/wave_loop.hpp"

namespace clrt {
namespace {

// Its kernel's parameters (kernels/megakernel.cl), bound by name.
struct MegakernelArgs {
  static constexpr const char* kName = "megakernel";
  SceneArgs scene;
  Global<const dev::RenderParams> params;
  Global<const dev::Camera> camera;
  Global<const dev::Material> materials;
  Global<const dev::Texture> textures;
  Global<const cl_uint> texels;
  Global<const dev::Light> lights;
  WaveArgs wave;
  Global<dev::f4> sample_colour;
  Global<cl_uint> ray_counts;  // CLRT_RAY_KINDS per camera sample

  CLRT_KERNEL_ARGS(scene, params, camera, materials, textures, texels, lights, wave, sample_colour, ray_counts)
};

// Its own buffers, X(member, element, length in elements of WaveSizes s, name).
#define CLRT_MEGAKERNEL_BUFFERS(X) \
  X(ray_counts_, cl_uint, CLRT_RAY_KINDS * s.capacity, "ray count")

// Its waves are the wavefront's (the same pixels per wave); it needs no shadow slots.
WaveSizes megakernel_sizes(const IntegratorConfig& config, const DeviceFrame& frame) {
  return wave_sizes(config.capacity, frame.host.camera.samples, 0);
}

// The deepest ray tree its private stack holds, and with one more its sums per level (path
// mode's last ray lies one level past the maximum depth). A CPU's stack lives in the caches, so
// a deep one costs nothing until it is used; a GPU's spills to slow memory, so it is kept at 16
// levels there (more than any shipped scene uses).
std::uint32_t stack_depth(DeviceClass device_class) {
  return device_class == DeviceClass::Cpu ? 32 : 16;
}

std::string megakernel_program_options(DeviceClass device_class) {
  return "-DCLRT_MEGAKERNEL_DEPTH=" + std::to_string(stack_depth(device_class));
}

void check_stack_depth(std::uint32_t max_depth, DeviceClass device_class) {
  if (max_depth > stack_depth(device_class))
    throw UsageError("the megakernel's ray stack holds trees of depth " +
                     std::to_string(stack_depth(device_class)) +
                     " on this device, the maximum depth is " + std::to_string(max_depth) +
                     ": lower --max-depth or use --integrator wavefront");
}

std::vector<DeviceBuffer> megakernel_own_buffers(const WaveSizes& s) {
  return {CLRT_MEGAKERNEL_BUFFERS(CLRT_BUFFER_DESCRIBE)};
}

std::vector<DeviceBuffer> megakernel_buffers(const WaveSizes& s) {
  return WaveLoop::with_resolver(megakernel_own_buffers(s), s);
}

class MegakernelIntegrator final : public WaveLoop {
 public:
  MegakernelIntegrator(DeviceContext& device, const compute::program& program,
                       const DeviceFrame& frame, const IntegratorConfig& config)
      : WaveLoop(device, program, frame, config, megakernel_sizes(config, frame), 1),
        sizes_(megakernel_sizes(config, frame)),
        megakernel_(program) {
    check_stack_depth(frame.host.params.max_depth, config.device_class);
    const WaveSizes& s = sizes_;
    CLRT_MEGAKERNEL_BUFFERS(CLRT_BUFFER_ALLOCATE)
  }

 private:
  // Every sample's colour is written whole, so the wave needs no clearing first, and its tree
  // lives on the stack, so it never overflows.
  bool trace(const WaveArgs& wave) override {
    launcher().launch(megakernel_,
                      {frame().geometry.args(), frame().params, frame().camera, frame().materials, frame().textures, frame().texels,
                       frame().lights, wave, resolver().sample_colour(), ray_counts_},
                      wave.sample_count, 0);
    profiler().count_rows(ray_counts_, wave.sample_count, 0);
    return true;
  }
  std::uint64_t own_bytes() const override {
    std::uint64_t bytes = 0;
    for (const DeviceBuffer& b : megakernel_own_buffers(sizes_)) bytes += b.bytes;
    return bytes;
  }

  WaveSizes sizes_;
  CLRT_MEGAKERNEL_BUFFERS(CLRT_BUFFER_MEMBER)
  TypedKernel<MegakernelArgs> megakernel_;
};

}  // namespace

const IntegratorEntry& megakernel_integrator() {
  static const IntegratorEntry entry{
      "megakernel",
      "one kernel walks each camera sample's whole ray tree (the design compared with)",
      megakernel_program_options,
      [](const RenderOptions& options, const DeviceProfile& profile) {
        check_stack_depth(static_cast<std::uint32_t>(options.max_depth), profile.device_class);
      },
      megakernel_buffers, make_integrator<MegakernelIntegrator>,
      kernel_binding_mismatches<MegakernelArgs>};
  return entry;
}

}  // namespace clrt
