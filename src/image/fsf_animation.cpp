#include "image/fsf_animation.hpp"

#include <unistd.h>

#include "image/atomic_file.hpp"
#include "image/encoders.hpp"

namespace clrt {

FsfAnimationWriter::FsfAnimationWriter(const ImageOutput& output, int width, int height,
                                       std::uint32_t frames)
    : name_(output.is_stdout() ? "standard output" : output.path),
      width_(width),
      height_(height),
      frames_(frames) {
  if (output.format != ImageFormat::Fsf)
    throw ImageError("cannot write " + name_ + ": an animation in one file needs FSF");
  if (output.is_stdout())
    sink_ = std::make_unique<image_detail::FdSink>(STDOUT_FILENO, name_);
  else
    sink_ = std::make_unique<image_detail::AtomicFile>(output.path);
  image_detail::write_fsf_header(width, height, frames, *sink_);
}

FsfAnimationWriter::~FsfAnimationWriter() = default;

void FsfAnimationWriter::add_frame(const FloatImage& frame) {
  add_rows(image_detail::EightBitRows(frame));
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
