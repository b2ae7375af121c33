// How clrt keeps a stopped render's work and goes on from it
// (docs/cli.md#stopping-and-resuming-a-render):
// while the rounds of samples run, a first SIGINT or SIGTERM asks the render to stop after the
// round in progress (image/interrupt_cleanup.hpp); the image of the samples taken is written as
// usual, and beside it the resume state (cli/resume_state.hpp) that --resume goes on from.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/animation_options.hpp"
#include "cli/options.hpp"
#include "cli/resume_state.hpp"
#include "render/renderer.hpp"

namespace clrt {

class ResumePlan {
 public:
  // With --resume, reads the output's state if there is one: a UsageError when --resume cannot
  // keep a state for this output (standard output, a device or FIFO, --no-write, an FSF
  // animation) or the state is not this render's (resume_state.hpp).
  ResumePlan(const CliOptions& cli, const ImageOutput& output, const FramePlan& frames,
             const Scene& scene, const RenderOptions& options);

  // Whether a stop request keeps the work: an output that is a file (or numbered files).
  bool keeps_work() const { return keeps_work_; }
  // The first frame left to render: the state's, else the plan's first.
  std::uint32_t first_frame() const { return state_ ? state_->frame : frames_.first; }
  // What was resumed, for the terminal ("resuming out.png at 16/64 spp"); empty when nothing was.
  std::string resumed_text() const;

  // The render of `frame`: from the state's sums when it is the state's frame, stopping between
  // rounds on request when the work is kept.
  ResumableRender start(std::uint32_t frame);
  // After the render of `frame` to `written`, which has been written: when it finished the last
  // frame, keeps the state (--resume on a still, to add samples later) or removes any; when a
  // stop was requested, writes the state to go on from (unless nothing is left to render) and
  // returns what to tell the terminal before clrt ends by the signal.
  std::optional<std::string> finish_frame(std::uint32_t frame, ResumableRender& render,
                                          const std::string& written);
  // "TAKEN/ASKED" for a render stopped early, else empty (WriteOptions::samples).
  std::string samples_note(const ResumableRender& render) const;
  const std::string& state_path() const { return path_; }

 private:
  const ResumeKey& key();

  FramePlan frames_;
  std::uint32_t samples_;  // asked, per pixel
  bool keeps_work_ = false, resume_ = false;
  std::string output_name_, path_;
  std::vector<std::string> files_;
  RenderOptions options_;
  std::optional<ResumeKey> key_;  // read from the files when a state is first read or written
  std::optional<ResumeState> state_;
  unsigned rounds_run_ = 0;  // over every frame, for hold_after_round_for_tests
};

}  // namespace clrt
