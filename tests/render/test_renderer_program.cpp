// The renderer's program per device and mode carries every integrator's own options after the
// device profile's, then the mode's transport model, so one build serves every scene and
// integrator of a mode.
#include <catch2/catch.hpp>

#include <string>

#include "cl_fixture.hpp"
#include "device/device_profile.hpp"
#include "render/integrator.hpp"
#include "shared/scene.h"

using namespace clrt;

TEST_CASE("the renderer's program is built with every integrator's options and the mode's model",
          "[integrators]") {
  const compute::device& device = test::device().device();
  const DeviceClass device_class = classify(device);
  struct Mode {
    RenderMode mode;
    dev::u32 model;
  };
  for (const Mode& m : {Mode{RenderMode::Trace, CLRT_MODE_TRACE}, Mode{RenderMode::Cast, CLRT_MODE_CAST},
                        Mode{RenderMode::Path, CLRT_MODE_PATH}}) {
    INFO("model " << m.model);
    const std::string built =
        test::renderer_program(m.mode).get_build_info<std::string>(CL_PROGRAM_BUILD_OPTIONS, device);
    CHECK(built == device_profile(device).program_options + " " +
                       integrator_program_options(device_class) +
                       " -DCLRT_TRANSPORT=" + std::to_string(m.model));
    for (const IntegratorEntry& entry : integrator_table()) {
      INFO(entry.name);
      const std::string own = entry.program_options(device_class);
      if (!own.empty()) CHECK((built + " ").find(" " + own + " ") != std::string::npos);
    }
  }
}

TEST_CASE("the megakernel's stack depth is its class's, as docs/devices.md gives it",
          "[integrators]") {
  const IntegratorEntry& megakernel = integrator_entry("megakernel");
  CHECK(megakernel.program_options(DeviceClass::Cpu) == "-DCLRT_MEGAKERNEL_DEPTH=32");
  CHECK(megakernel.program_options(DeviceClass::Gpu) == "-DCLRT_MEGAKERNEL_DEPTH=16");
  CHECK(megakernel.program_options(DeviceClass::Other) == "-DCLRT_MEGAKERNEL_DEPTH=16");
  CHECK(integrator_entry("wavefront").program_options(DeviceClass::Cpu).empty());
  CHECK(integrator_program_options(DeviceClass::Gpu) == "-DCLRT_MEGAKERNEL_DEPTH=16");
}
