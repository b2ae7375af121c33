// clrt's whole command, once its command line is parsed: every check that can come before the
// work, the render of each frame, the writes, --stats. Returns the exit status (0 ok, 1 runtime
// failure, 2 usage or scene error); errors are printed as "clrt: error: ...", scene errors as
// FILE:LINE:COLUMN: error: ....
#pragma once

#include <vector>

#include "cli/options.hpp"
#include "device/device_select.hpp"
#include "geometry/geometry_data.hpp"
#include "render/renderer.hpp"

namespace clrt {

int run_clrt(const CliOptions& cli);

// The steps clrt-mpi shares with clrt:
// the output, checked before any work (UsageError); with --no-write, one without a path;
ImageOutput resolve_image_output(const CliOptions& cli, const FramePlan& frames);
inline bool writes_nothing(const ImageOutput& output) { return output.path.empty(); }
// that the output's file system has room for the image, where its size is known in advance
// (RenderLimitError, exit 1);
void check_output_space(const ImageOutput& output, const FramePlan& frames,
                        const PixelRect& region);
// that no output overwrites the scene or a mesh it read (UsageError);
void check_outputs_are_not_inputs(const ImageOutput& output, const FramePlan& frames,
                                  const Scene& scene);
// the render settings on `devices`, with every limit checked (UsageError, RenderLimitError);
RenderSetup checked_render_setup(const CliOptions& cli, const Scene& scene,
                                 std::vector<DeviceEntry> devices);
// the BVH, after which the scene's meshes are freed.
GeometryData built_geometry(Scene& scene, Progress& progress);

}  // namespace clrt
