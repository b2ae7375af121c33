#include "memory_need.hpp"

#include <filesystem>
#include <system_error>

#include "image/checked_size.hpp"
#include "scene/memory_limit.hpp"

namespace clrt::img {
namespace {

constexpr std::uint64_t kSaturated = UINT64_MAX;

std::uint64_t product(std::uint64_t a, std::uint64_t b) {
  return image_detail::checked_mul(a, b).value_or(kSaturated);
}

// Bytes a pixel takes in memory: RGBA bytes, or RGB floats.
std::uint64_t held_bytes_per_pixel(bool held_float) { return held_float ? 12 : 4; }

// What an 8-bit frame costs beyond its pixels: each is a vector of its own, 24 bytes, and an
// allocation with the allocator's header and rounding. Measured: 5M frames of 1x1 held 56 bytes
// each beyond their 4 (a 20 MB FSF peaked at 426 MB converting to GIF, estimated at 60 MB
// before this was counted).
constexpr std::uint64_t kFrameOverhead = 64;

// What the encoder holds whole: PNG its compressed bands, EXR its file (reserved at the raw
// samples' size); FSF, PPM and PFM are written row by row.
std::uint64_t encoded_bytes_per_pixel(ImageFormat format, ExrPixel exr_pixel) {
  if (format == ImageFormat::Exr) return exr_pixel == ExrPixel::Float ? 12 : 6;
  return format == ImageFormat::Png ? 4 : 0;
}

}  // namespace

void MemoryNeed::add(std::uint64_t bytes) {
  bytes_ = bytes > kSaturated - bytes_ ? kSaturated : bytes_ + bytes;
}

void MemoryNeed::add_pixels(std::uint64_t pixels, std::uint64_t frames,
                            std::uint64_t bytes_per_pixel) {
  add(product(product(pixels, frames), bytes_per_pixel));
}

void MemoryNeed::add_read(const std::string& path, const ImageInfo& info) {
  std::error_code error;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, error);
  if (!error) add(file_bytes);
  add_pixels(pixels_of(info), info.frames, held_bytes_per_pixel(reads_as_float(info.format)));
  if (!reads_as_float(info.format)) add(product(info.frames, kFrameOverhead));
}

void MemoryNeed::add_float_frames(std::uint64_t pixels, std::uint64_t frames) {
  add_pixels(pixels, frames, held_bytes_per_pixel(true));
}

void MemoryNeed::add_gif_write(std::uint64_t pixels, std::uint64_t frames, bool held_float) {
  // A float image is quantised whole into 8-bit frames first; the GIF itself is streamed to
  // its file.
  if (held_float) {
    add_pixels(pixels, frames, held_bytes_per_pixel(false));
    add(product(frames, kFrameOverhead));
  }
}

void MemoryNeed::add_write(std::uint64_t pixels, std::uint64_t frames, bool held_float,
                           ImageFormat written, ExrPixel exr_pixel) {
  // An 8-bit image is copied whole as floats for PFM and EXR; a float one is quantised a row at
  // a time for the others.
  if (!held_float && reads_as_float(written)) add_pixels(pixels, frames, held_bytes_per_pixel(true));
  add_pixels(pixels, frames, encoded_bytes_per_pixel(written, exr_pixel));
}

std::uint64_t pixels_of(const ImageInfo& info) {
  return product(static_cast<std::uint64_t>(info.width), static_cast<std::uint64_t>(info.height));
}

bool reads_as_float(ImageFormat format) {
  return format == ImageFormat::Pfm || format == ImageFormat::Exr;
}

void check_memory(const MemoryNeed& need, const std::string& what) {
  const MemoryLimit limit = memory_limit();
  if (need.bytes() <= limit.bytes) return;
  throw ImageError(what + " needs " + mebibytes(need.bytes()) + ", " + mebibytes(limit.bytes) +
                   " available (" + limit.source + ")");
}

}  // namespace clrt::img
