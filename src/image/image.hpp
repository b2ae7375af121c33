// Images in memory and on disk: linear float RGB as rendered, 8-bit RGBA as stored.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "image/byte_span.hpp"
#include "image/display_transform.hpp"
#include "image/png_encoding.hpp"

namespace clrt {

// Where an image lies in a larger frame: its top-left pixel is (x, y) of a full_width x
// full_height frame. A farm renders a frame as such tiles and stitches them (docs/images.md).
struct Placement {
  int x = 0, y = 0;
  int full_width = 0, full_height = 0;
  bool operator==(const Placement& other) const {
    return x == other.x && y == other.y && full_width == other.full_width &&
           full_height == other.full_height;
  }
  bool operator!=(const Placement& other) const { return !(*this == other); }
};

// The renderer's output: linear RGB, unclamped, row 0 at the top. No placement: the image is
// the whole frame.
struct FloatImage {
  FloatImage() = default;
  // The constructors keep the many whole-image call sites short.
  FloatImage(int width_, int height_, std::vector<float> rgb_,
             std::optional<Placement> placement_ = std::nullopt)
      : width(width_), height(height_), rgb(std::move(rgb_)), placement(placement_) {}

  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 * width * height
  std::optional<Placement> placement;
};

// 8-bit RGBA, row 0 at the top; one entry per frame (FSF can hold an animation).
struct Rgba8Image {
  Rgba8Image() = default;
  Rgba8Image(int width_, int height_, std::vector<std::vector<std::uint8_t>> frames_,
             std::optional<Placement> placement_ = std::nullopt)
      : width(width_), height(height_), frames(std::move(frames_)), placement(placement_) {}

  int width = 0, height = 0;
  std::vector<std::vector<std::uint8_t>> frames;  // each 4 * width * height
  std::optional<Placement> placement;
};

class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An input that is not a regular file (a FIFO, a device, a socket, a folder), refused before it
// is read: wrong on the command line's face, so a usage error (exit 2) for every tool, as a
// scene or texture that is no file is for clrt.
class NotAFileError : public ImageError {
 public:
  using ImageError::ImageError;
};

// The contract's quantisation: clamp each channel to [0, 1], scale by 255, round to nearest;
// alpha 255. With a display transform, each value goes through it first.
Rgba8Image quantize(const FloatImage& image, const DisplayTransform& display = {});
// Frame `frame` as value / 255 per channel (exact in float, and quantize() gives the bytes back);
// alpha is dropped.
FloatImage to_float(const Rgba8Image& image, std::size_t frame = 0);

enum class ImageFormat { Fsf, Png, Ppm, Pfm, Exr };

// By the path's extension (case-insensitive: .fsf .png .ppm .pfm .exr); throws ImageError
// otherwise.
ImageFormat format_from_path(const std::string& path);
// The same without the error: nothing for a path whose extension names no format.
std::optional<ImageFormat> format_of_extension(const std::string& path);
// By a name as --format takes it: fsf, png, ppm, pfm, exr (case-insensitive); ImageError otherwise.
ImageFormat format_from_name(const std::string& name);
std::string format_name(ImageFormat format);   // "png"
std::vector<std::string> format_names();       // every name format_from_name takes
bool holds_floats(ImageFormat format);          // PFM and EXR; the others store 8-bit samples

// OpenEXR channels: 16-bit half floats (the default: 3 significant decimal digits, a third of
// float's size once compressed) or 32-bit floats (exactly what was rendered).
enum class ExrPixel { Half, Float };

// The name a stopped render's sample count is recorded under (WriteOptions::samples).
constexpr const char* kSamplesKey = "clrt:samples";

struct WriteOptions {
  // A constructor rather than an aggregate, so that callers may name the leading options only
  // ({ExrPixel::Float}) without a missing-initializer warning.
  WriteOptions(ExrPixel exr_pixel_ = ExrPixel::Half, PngEncoding png_ = {})
      : exr_pixel(exr_pixel_), png(png_) {}

  ExrPixel exr_pixel;
  PngEncoding png;  // a level outside 0-9 is an ImageError before anything is written
  // How a float image becomes 8-bit (PNG, PPM, FSF); PFM and EXR keep the floats, and an 8-bit
  // image's bytes are written as they are.
  DisplayTransform display;
  // The samples per pixel of a render stopped early, as "TAKEN/ASKED" (clrt's Ctrl-C): PNG
  // keeps it in a tEXt chunk and EXR in a string attribute, both named kSamplesKey; the other
  // formats cannot hold it. Empty for a finished render: nothing is recorded.
  std::string samples;
  // Told, once per image, what its format could not hold ("out.exr: 12 of the 300 samples ...":
  // finite values beyond a half float's range); nothing: not told.
  std::function<void(const std::string&)> warn;
};

// Writes `image` in the format its extension names (PNG for a device or FIFO without one). PFM
// and EXR keep the unclamped floats; the others quantise. A file is written to a temporary
// beside it (beside a link's target, for a link) and renamed into place, so a failure (thrown
// as ImageError naming the path and the reason) leaves nothing behind; a device or FIFO is
// written straight through (output_target.hpp). PNG and EXR record a placement; FSF, PPM and
// PFM cannot hold one and drop it.
void write_image(const std::string& path, const FloatImage& image,
                 const WriteOptions& options = {});
void write_image(const std::string& path, const Rgba8Image& image,  // PNG/PPM/PFM/EXR: frame 0
                 const WriteOptions& options = {});

// An output named on a command line: a file, or "-" for standard output; the format given
// explicitly or, for a file, by its extension.
struct ImageOutput {
  std::string path;
  ImageFormat format = ImageFormat::Png;
  bool is_stdout() const { return path == "-"; }
};
constexpr const char* kStdoutPath = "-";
// Checks what can be checked before any work: "-" needs `format` and a standard output that is
// not a terminal; a folder is refused; a file's extension, when it names a format, must agree
// with `format`; without `format`, a device or FIFO whose name has no known extension gets PNG.
ImageOutput resolve_output(const std::string& path, std::optional<ImageFormat> format);
// A file as write_image(path) writes it; standard output through write_image_to_fd.
void write_image(const ImageOutput& output, const FloatImage& image,
                 const WriteOptions& options = {});
void write_image(const ImageOutput& output, const Rgba8Image& image,
                 const WriteOptions& options = {});
// The whole encoded image to an open descriptor (standard output for `-o -`), the format given
// explicitly. A pipe cannot be written atomically: on failure the reader may have received part.
void write_image_to_fd(int fd, ImageFormat format, const FloatImage& image,
                       const WriteOptions& options = {});
void write_image_to_fd(int fd, ImageFormat format, const Rgba8Image& image,
                       const WriteOptions& options = {});

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

// PNG: any bit depth and colour type, as 8-bit RGBA (16-bit samples rounded to 8 bits); samples
// are taken as they are (no gamma or ICC conversion). The placement comes from clrt's text chunk.
Rgba8Image read_png(const std::string& path);
// PPM: binary P6 or plain P3, any maxval up to 65535 (scaled to 255, rounded); alpha 255.
Rgba8Image read_ppm(const std::string& path);
// PFM: colour (PF) or grey (Pf, copied to R, G and B), either byte order, times |scale|.
FloatImage read_pfm(const std::string& path);
// OpenEXR: the R, G and B channels (or Y copied to all three) of the data window, as floats; the
// data window's place in the display window is the placement.
FloatImage read_exr(const std::string& path);
// By the path's extension; 8-bit formats as they are, PFM and EXR quantised.
Rgba8Image read_image(const std::string& path);
// An image as its file stores it: 8-bit frames (FSF, PNG, PPM) or floats (PFM, EXR).
using AnyImage = std::variant<Rgba8Image, FloatImage>;
AnyImage read_any_image(const std::string& path);

// Which frames of an animated file (FSF) to decode: a texture or an environment shows the first,
// and the others then cost neither time nor memory.
enum class Frames { All, First };
// An image from its file's bytes in memory, decoded in place, in `format`; a file whose content is
// another known format is refused naming that format. Messages name `file.name`.
AnyImage decode_image(const ImageBytes& file, ImageFormat format, Frames frames = Frames::All);

// A one-frame image holding frame `frame` of `image`, counted from 1 as clrt numbers the files
// of an animation; ImageError if out of range.
Rgba8Image select_frame(const Rgba8Image& image, int frame);

}  // namespace clrt
