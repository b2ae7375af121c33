// Where a render's pixels go as its waves finish: linear floats for formats that keep them
// (PFM, EXR), or 8-bit RGBA quantised as the contract says for the others, a quarter of the
// memory of a float image. Pixels are numbered in row-major order of the rendered region.
#pragma once

#include <cstdint>

#include "image/image.hpp"
#include "shared/common.h"

namespace clrt {

class PixelStore {
 public:
  virtual ~PixelStore() = default;
  // Pixels [first, first + count) of the region, RGB in xyz.
  virtual void store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) = 0;
};

class FloatPixelStore final : public PixelStore {
 public:
  explicit FloatPixelStore(FloatImage& image) : image_(image) {}
  void store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) override;

 private:
  FloatImage& image_;
};

// Stores into `image`, then hands the same pixels to `watcher` (clrt --preview).
class BytePixelStore final : public PixelStore {
 public:
  explicit BytePixelStore(Rgba8Image& image) : image_(image) {}  // frame 0
  void store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) override;

 private:
  Rgba8Image& image_;
};

}  // namespace clrt
