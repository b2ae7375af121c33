// clrt's resume state (docs/cli.md#stopping-and-resuming-a-render): what a render stopped
// between rounds of samples leaves beside its output, OUTPUT.clrt-resume, to go on from with
// --resume: every pixel's sums of the samples taken, as the rounds leave them, so that the
// render that goes on has the bits of one that never stopped.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/animation_options.hpp"
#include "render/render_options.hpp"
#include "scene/scene.hpp"
#include "shared/scene.h"

namespace clrt {

// What a state must have been rendered with to be gone on from: the bytes of the scene's files
// (the scene, its meshes, its texture and environment images) and the options that change the
// image's sums. The samples per pixel belong to them unless the sampler draws sample k whatever
// the total (path mode), where samples may be added later.
struct ResumeKey {
  std::string files;    // a hash of the files' bytes
  std::string options;  // "name=value" words
};
// The files a scene was read from: the scene, its meshes, its texture and environment images.
std::vector<std::string> scene_files(const Scene& scene);
// Reads every file of `files` (only when a state is read or written: a large mesh costs its
// read again).
ResumeKey resume_key(const std::vector<std::string>& files, const RenderOptions& options,
                     const FramePlan& frames);

struct ResumeState {
  std::uint32_t frame = 1;    // the frame the sums belong to; an animation's earlier ones are done
  std::uint32_t samples = 0;  // per pixel, taken
  std::vector<dev::f4> sums;  // every pixel of the region's, rows from the top
};

// The state's path for an output: OUTPUT.clrt-resume (an animation's numbered frames share
// the one of the name given with -o).
std::string resume_state_path(const std::string& output);

// Writes the state atomically (the same temporary and rename as an image).
void write_resume_state(const std::string& path, const ResumeKey& key, const ResumeState& state);

// The state at `path`, or nothing when there is none. A state for another key (naming what
// differs), for another number of pixels or not a state at all is a UsageError.
std::optional<ResumeState> read_resume_state(const std::string& path, const ResumeKey& key,
                                             std::uint64_t pixels);

}  // namespace clrt
