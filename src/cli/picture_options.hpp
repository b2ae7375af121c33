// --exposure and --tonemap: how clrt's 8-bit outputs turn the render's linear values into
// bytes, sRGB-encoded in path mode (docs/images.md#from-linear-values-to-bytes).
#pragma once

#include <CLI/CLI.hpp>

#include "cli/options.hpp"

namespace clrt {

void add_picture_options(CLI::App& app, CliOptions& o);

// The transform of the 8-bit outputs: the options' exposure and curve; path mode's values are
// radiance and get sRGB's encoding, the Whitted modes' colours are display values already and
// are written as computed.
DisplayTransform display_transform(const CliOptions& cli, RenderMode mode);

// UsageError when --exposure or --tonemap is asked of an output that keeps floats (PFM, EXR):
// they stay linear and unclamped.
void check_picture_output(const CliOptions& cli, const ImageOutput& output);

// Whether the renderer may hand back bytes, quantised as it goes (a quarter of a float image's
// memory): for an 8-bit output whose transform is the contract's quantisation alone.
bool renders_bytes(const ImageOutput& output, const DisplayTransform& display);

}  // namespace clrt
