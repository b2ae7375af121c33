#include "cli/resume_plan.hpp"

#include <filesystem>

#include "image/interrupt_cleanup.hpp"
#include "image/output_target.hpp"
#include "render/usage_error.hpp"

namespace clrt {
namespace {

// Why an output cannot keep a resume state, or empty when it can.
std::string why_no_state(const CliOptions& cli, const ImageOutput& output,
                         const FramePlan& frames) {
  if (cli.no_write) return "--no-write writes no image";
  if (output.is_stdout()) return "standard output keeps nothing to go on from";
  if (frames.animated && output.format == ImageFormat::Fsf)
    return "an FSF animation is one file written frame by frame";
  if (find_output_target(output.path).stream) return output.path + " is not a regular file";
  return {};
}

}  // namespace

ResumePlan::ResumePlan(const CliOptions& cli, const ImageOutput& output, const FramePlan& frames,
                       const Scene& scene, const RenderOptions& options)
    : frames_(frames), samples_(static_cast<std::uint32_t>(options.samples)), resume_(cli.resume) {
  const std::string why = why_no_state(cli, output, frames);
  if (!why.empty()) {
    if (cli.resume) throw UsageError("--resume needs an image file to keep a state beside: " + why);
    return;
  }
  keeps_work_ = true;
  output_name_ = output.path;
  path_ = resume_state_path(output.path);
  files_ = scene_files(scene);
  options_ = options;
  if (!cli.resume) return;
  state_ = read_resume_state(path_, key(), render_region(options).pixel_count());
  if (!state_) return;
  if (state_->frame < frames.first || state_->frame > frames.last)
    throw UsageError("--resume: " + path_ + " is at frame " + std::to_string(state_->frame) +
                     ", outside the frames asked for");
  if (state_->samples > samples_)
    throw UsageError("--resume: " + path_ + " has " + std::to_string(state_->samples) +
                     " samples per pixel already; --spp " + std::to_string(samples_) +
                     " cannot take them away (give at least " + std::to_string(state_->samples) +
                     ")");
}

const ResumeKey& ResumePlan::key() {
  if (!key_) key_ = resume_key(files_, options_, frames_);
  return *key_;
}

std::string ResumePlan::resumed_text() const {
  if (!state_) return resume_ && keeps_work_ ? "no " + path_ + " yet: starting from 0 spp" : "";
  const std::string at_frame =
      frames_.animated ? " at frame " + std::to_string(state_->frame) : "";
  return "resuming " + output_name_ + at_frame + " from " + std::to_string(state_->samples) + "/" + std::to_string(samples_) + " spp (" +
         path_ + ")";
}

ResumableRender ResumePlan::start(std::uint32_t frame) {
  ResumableRender render;
  if (state_ && state_->frame == frame) {
    render.samples = state_->samples;
    render.sums = std::move(state_->sums);
    state_.reset();
  }
  render.keep_finished_sums = resume_ && !frames_.animated;
  if (keeps_work_)
    render.stop = [this](std::uint32_t) {
      hold_after_round_for_tests(++rounds_run_);
      return stop_request() != 0;
    };
  return render;
}

std::optional<std::string> ResumePlan::finish_frame(std::uint32_t frame, ResumableRender& render,
                                                    const std::string& written) {
  if (!keeps_work_) return std::nullopt;
  const bool stopping = stop_request() != 0;
  const bool done = render.samples == samples_;
  const std::string stopped = "clrt: stopped: wrote " + written + " with " +
                              std::to_string(render.samples) + "/" + std::to_string(samples_) +
                              " samples per pixel";
  if (stopping && (!done || frame < frames_.last)) {
    ResumeState state;
    state.frame = done ? frame + 1 : frame;
    if (!done) {
      state.samples = render.samples;
      state.sums = std::move(render.sums);
    }
    write_resume_state(path_, key(), state);
    return stopped + "; --resume goes on from " + path_;
  }
  if (frame < frames_.last) return std::nullopt;
  // The last frame is whole: a still rendered with --resume keeps its sums to add samples to.
  if (resume_ && !frames_.animated) {
    ResumeState state;
    state.samples = render.samples;
    state.sums = std::move(render.sums);
    write_resume_state(path_, key(), state);
  } else {
    std::error_code absent;
    std::filesystem::remove(path_, absent);
  }
  if (!stopping) return std::nullopt;
  return stopped;
}

std::string ResumePlan::samples_note(const ResumableRender& render) const {
  if (!keeps_work_ || render.samples == samples_) return {};
  return std::to_string(render.samples) + "/" + std::to_string(samples_);
}

}  // namespace clrt
