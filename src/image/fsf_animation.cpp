#include "image/fsf_animation.hpp"

#include "image/byte_sink.hpp"
#include "image/encoders.hpp"
#include "image/output_target.hpp"

namespace clrt {

FsfAnimationWriter::FsfAnimationWriter(const ImageOutput& output, int width, int height,
                                       std::uint32_t frames, const DisplayTransform& display)
    : name_(output.is_stdout() ? "standard output" : output.path),
      display_(display),
      width_(width),
      height_(height),
      frames_(frames) {
  if (output.format != ImageFormat::Fsf)
    throw ImageError("cannot write " + name_ + ": an animation in one file needs FSF");
  sink_ = image_detail::open_output_sink(output);
  image_detail::write_fsf_header(width, height, frames, *sink_);
}

FsfAnimationWriter::~FsfAnimationWriter() = default;

void FsfAnimationWriter::add_frame(const FloatImage& frame) {
  add_rows(image_detail::EightBitRows(frame, display_));
}

void FsfAnimationWriter::add_frame(const Rgba8Image& frame) {
  add_rows(image_detail::EightBitRows(frame));
}

void FsfAnimationWriter::add_rows(const image_detail::EightBitRows& rows) {
  if (rows.width() != width_ || rows.height() != height_ || written_ == frames_)
    throw ImageError("cannot write " + name_ + ": a frame that does not fit the animation");
  image_detail::write_fsf_frame(rows, 0, *sink_);
  ++written_;
}

void FsfAnimationWriter::finish() {
  if (written_ != frames_)
    throw ImageError("cannot write " + name_ + ": " + std::to_string(written_) + " of " +
                     std::to_string(frames_) + " frames were rendered");
  sink_->finish();
}

}  // namespace clrt
