// 8-bit rows for the PNG, PPM and FSF writers, from either kind of image, one row at a time: a
// float image goes through its display transform and is quantised row by row into a scratch
// row, never copied whole; an 8-bit image's bytes are written as they are.
#pragma once

#include <cstddef>
#include <cstdint>

#include "image/display_transform.hpp"
#include "image/image.hpp"

namespace clrt::image_detail {

class EightBitRows {
 public:
  explicit EightBitRows(const FloatImage& image, const DisplayTransform& display = {})
      : float_(&image), display_(display) {}
  explicit EightBitRows(const Rgba8Image& image) : rgba_(&image) {}

  int width() const { return float_ ? float_->width : rgba_->width; }
  int height() const { return float_ ? float_->height : rgba_->height; }
  std::size_t frames() const { return float_ ? 1 : rgba_->frames.size(); }
  const std::optional<Placement>& placement() const {
    return float_ ? float_->placement : rgba_->placement;
  }
  // Whether every alpha of frame 0 is 255 (always, for a float image).
  bool opaque() const;

  // Row y of `frame` as RGBA (4 bytes a pixel) or RGB (3). `scratch` holds 4 * width() bytes; the
  // result points into it or, when nothing needs converting, straight into the image.
  const std::uint8_t* rgba_row(std::size_t frame, int y, std::uint8_t* scratch) const noexcept;
  const std::uint8_t* rgb_row(std::size_t frame, int y, std::uint8_t* scratch) const noexcept;

 private:
  const FloatImage* float_ = nullptr;
  const Rgba8Image* rgba_ = nullptr;
  DisplayTransform display_;
};

// The contract's quantisation of one channel (see quantize()).
std::uint8_t quantize_channel(float value) noexcept;

}  // namespace clrt::image_detail
