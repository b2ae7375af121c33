// What a command will hold at its peak, estimated from the headers before any pixel is
// decoded, and the check of it against the memory this process may take: a PNG or EXR of a
// few hundred kilobytes may declare 2^28 pixels, gigabytes once decoded.
#pragma once

#include <cstdint>
#include <string>

#include "image/image_info.hpp"

namespace clrt::img {

// Sums and products of byte counts that stay at UINT64_MAX once past it.
class MemoryNeed {
 public:
  void add(std::uint64_t bytes);
  // `pixels` of `frames` frames at `bytes_per_pixel`.
  void add_pixels(std::uint64_t pixels, std::uint64_t frames, std::uint64_t bytes_per_pixel);
  // Reading `path`: the file itself, held while it is decoded, and its pixels decoded (an 8-bit
  // image's frames each with its own allocation's overhead).
  void add_read(const std::string& path, const ImageInfo& info);
  // Writing `pixels` of `frames` frames, held as floats or 8-bit, as `written`: a copy as
  // floats for a float format, and what the encoder holds whole, counted at the raw samples'
  // size.
  void add_write(std::uint64_t pixels, std::uint64_t frames, bool held_float,
                 ImageFormat written, ExrPixel exr_pixel);
  // Every one of `frames` frames of `pixels` held once more as floats (a viewer's copy).
  void add_float_frames(std::uint64_t pixels, std::uint64_t frames);
  // Writing a GIF of `pixels` in `frames` frames, held as floats or 8-bit.
  void add_gif_write(std::uint64_t pixels, std::uint64_t frames, bool held_float);
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::uint64_t bytes_ = 0;
};

// The pixels of one frame of `info`.
std::uint64_t pixels_of(const ImageInfo& info);
// Whether reading `info`'s format gives a float image (PFM, EXR).
bool reads_as_float(ImageFormat format);

// Throws ImageError("<what> needs X MiB, Y MiB available (<the limit that counts>)") when
// `need` is more than this process may take (memory_limit()).
void check_memory(const MemoryNeed& need, const std::string& what);

}  // namespace clrt::img
