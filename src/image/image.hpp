// Images in memory and on disk: linear float RGB as rendered, 8-bit RGBA as stored.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace clrt {

// The renderer's output: linear RGB, unclamped, row 0 at the top.
struct FloatImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 * width * height
};

// 8-bit RGBA, row 0 at the top; one entry per frame (FSF can hold an animation).
struct Rgba8Image {
  int width = 0, height = 0;
  std::vector<std::vector<std::uint8_t>> frames;  // each 4 * width * height
};

class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The contract's quantisation: clamp each channel to [0, 1], scale by 255, round to nearest;
// alpha 255.
Rgba8Image quantize(const FloatImage& image);

enum class ImageFormat { Fsf, Png, Ppm, Pfm };

// By the path's extension (case-insensitive: .fsf .png .ppm .pfm); throws ImageError otherwise.
ImageFormat format_from_path(const std::string& path);

// Writes `image` in the format its extension names. PFM keeps the unclamped floats; the others
// quantise. The file is written to a temporary beside `path` and renamed into place, so a
// failure (thrown as ImageError naming the path and the reason) leaves nothing behind.
void write_image(const std::string& path, const FloatImage& image);
void write_image(const std::string& path, const Rgba8Image& image);  // PNG/PPM take frame 0

// FSF reader: either byte order (the magic 575 tells which); rejects a size that disagrees with
// the header. Throws ImageError.
Rgba8Image read_fsf(const std::string& path);
// The header alone (width, height, frames, byte order) for summaries.
struct FsfHeader {
  std::uint32_t width = 0, height = 0, frames = 0;
  bool big_endian = false;
};
FsfHeader read_fsf_header(const std::string& path);
// The size of the whole file the header describes (header included); ImageError if it does not
// fit in 64 bits.
std::uint64_t fsf_file_size(const FsfHeader& header);
// One "key: value" line each for width, height, frames, byte order and bytes (clrt-fsfconv --info).
std::string fsf_summary(const FsfHeader& header);

// Readers for converting into FSF. Both give one frame of 8-bit RGBA, row 0 at the top.
// PNG: any bit depth and colour type (16-bit samples are taken as sRGB-encoded, like 8-bit ones).
Rgba8Image read_png(const std::string& path);
// PPM: binary P6 or plain P3, any maxval up to 65535 (scaled to 255, rounded); alpha 255.
Rgba8Image read_ppm(const std::string& path);
// By the path's extension: .fsf, .png or .ppm (case-insensitive); ImageError otherwise.
Rgba8Image read_image(const std::string& path);

// A one-frame image holding frame `frame` (counted from 0) of `image`; ImageError if out of range.
Rgba8Image select_frame(const Rgba8Image& image, int frame);

}  // namespace clrt
