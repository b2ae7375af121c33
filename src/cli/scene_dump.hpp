// clrt --dump-scene: the scene as clrt reads it, written as JSON instead of rendered.
#pragma once

#include "cli/options.hpp"

namespace clrt {

// Loads cli.scene and writes it to *cli.dump_scene ("-": standard output) as
// docs/scene-json.md describes, never starting OpenCL. The output is checked before the scene
// loads, as an image's is (UsageError); a write that fails leaves no file (ImageError). Returns
// the exit status: 0, or 2 after printing a scene error.
int dump_scene(const CliOptions& cli);

}  // namespace clrt
