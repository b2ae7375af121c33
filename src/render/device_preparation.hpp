// A device with its context and the renderer's program, made before the scene is known, so
// OpenCL's start (the ICD loader opening PoCL: about 25 ms) and the build (about 30 ms from a
// warm kernel cache) can run while the scene loads. The program depends on the scene only
// through its SceneFeatures; it is prepared for a still scene without textures, the common case,
// and another scene has its own built once it is known (Renderer).
#pragma once

#include <memory>
#include <vector>

#include "device/device_context.hpp"
#include "device/device_select.hpp"
#include "render/render_options.hpp"
#include "render/renderer_program.hpp"

namespace clrt {

struct PreparedDevice {
  std::unique_ptr<DeviceContext> context;
  compute::program program;
  RenderMode mode = RenderMode::Trace;        // the transport model the program holds
  SceneFeatures features;                     // and what of the scene it holds code for: none
};

// The program for the render's mode (a command-line choice, known before the scene). Throws
// DeviceError with the build log of a program that does not build. `compiling` is called before
// a device's program is compiled from source (CompileNotice).
std::vector<PreparedDevice> prepare_devices(const std::vector<DeviceEntry>& devices, RenderMode mode,
                                            const CompileNotice& compiling = {});

}  // namespace clrt
