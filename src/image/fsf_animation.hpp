// An FSF animation written frame by frame, so that a long one never sits whole in memory: the
// header announces the frame count, each frame is quantised and appended as it is rendered.
#pragma once

#include <cstdint>
#include <memory>

#include "image/image.hpp"

namespace clrt {

namespace image_detail {
class ByteSink;
class EightBitRows;
}

class FsfAnimationWriter {
 public:
  // A file is written to a temporary and put in place by finish(); standard output is written
  // as frames come. Float frames go through `display`. Throws ImageError for an output that
  // cannot be opened.
  FsfAnimationWriter(const ImageOutput& output, int width, int height, std::uint32_t frames,
                     const DisplayTransform& display = {});
  ~FsfAnimationWriter();

  // The next frame; its size must be the animation's.
  void add_frame(const FloatImage& frame);
  void add_frame(const Rgba8Image& frame);
  // After the last frame. Destroyed before, a file leaves nothing behind.
  void finish();

 private:
  void add_rows(const image_detail::EightBitRows& rows);

  std::unique_ptr<image_detail::ByteSink> sink_;
  std::string name_;
  DisplayTransform display_;
  int width_, height_;
  std::uint32_t frames_, written_ = 0;
};

}  // namespace clrt
