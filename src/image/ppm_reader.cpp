// PPM as Netpbm defines it: "P6" (binary) or "P3" (plain), width, height and maxval as decimal
// numbers separated by whitespace and '#' comments, one whitespace character, then the samples
// (binary: one byte each, two big-endian bytes when maxval > 255). One image per file: trailing
// bytes are an error, as a truncated raster is.
#include <cctype>
#include <climits>

#include "image/checked_size.hpp"
#include "image/image.hpp"
#include "image/input_file.hpp"

namespace clrt {
namespace {

class PpmCursor {
 public:
  PpmCursor(const std::vector<std::uint8_t>& bytes, const std::string& path)
      : bytes_(bytes), path_(path) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw ImageError(path_ + ": not a readable PPM: " + what + " (at byte " + std::to_string(pos_) +
                     ")");
  }

  // Whitespace and comments are skipped first; a number may not exceed `max`.
  std::uint32_t number(const char* name, std::uint32_t min, std::uint32_t max) {
    skip_blanks();
    if (at_end() || !std::isdigit(bytes_[pos_])) fail(std::string("expected the ") + name);
    std::uint64_t value = 0;
    while (!at_end() && std::isdigit(bytes_[pos_])) {
      value = value * 10 + (bytes_[pos_++] - '0');
      if (value > max) fail(std::string("the ") + name + " exceeds " + std::to_string(max));
    }
    if (value < min) fail(std::string("the ") + name + " is below " + std::to_string(min));
    return static_cast<std::uint32_t>(value);
  }

  // "P6" (true) or "P3" (false).
  bool magic() {
    if (bytes_.size() < 3 || bytes_[0] != 'P' || (bytes_[1] != '6' && bytes_[1] != '3') ||
        !(std::isspace(bytes_[2]) || bytes_[2] == '#'))
      fail("it does not start with P6 or P3");
    pos_ = 2;
    return bytes_[1] == '6';
  }

  void skip_blanks() {
    while (!at_end()) {
      if (bytes_[pos_] == '#') {
        while (!at_end() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else if (std::isspace(bytes_[pos_])) {
        ++pos_;
      } else {
        return;
      }
    }
  }

  // The single whitespace character that ends a binary header.
  void header_end() {
    if (at_end() || !std::isspace(bytes_[pos_])) fail("expected whitespace after maxval");
    ++pos_;
  }

  bool at_end() const { return pos_ >= bytes_.size(); }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  const std::uint8_t* here() const { return bytes_.data() + pos_; }

 private:
  const std::vector<std::uint8_t>& bytes_;
  const std::string& path_;
  std::size_t pos_ = 0;
};

std::uint8_t to_8bit(std::uint32_t sample, std::uint32_t maxval) {
  return static_cast<std::uint8_t>((sample * 255u + maxval / 2) / maxval);
}

// Sample i of the file (R, G, B of pixel i / 3) goes to byte i + i / 3 of the RGBA frame.
void read_binary_samples(PpmCursor& cursor, std::uint32_t maxval, std::vector<std::uint8_t>& rgba) {
  const std::size_t sample_bytes = maxval > 255 ? 2 : 1;
  const std::uint8_t* in = cursor.here();
  for (std::size_t i = 0; i < rgba.size() / 4 * 3; ++i) {
    const std::uint8_t* sample_in = in + i * sample_bytes;
    const std::uint32_t sample =
        sample_bytes == 2 ? std::uint32_t{sample_in[0]} << 8 | sample_in[1] : sample_in[0];
    if (sample > maxval) cursor.fail("a sample exceeds maxval");
    rgba[i + i / 3] = to_8bit(sample, maxval);
  }
}

void read_plain_samples(PpmCursor& cursor, std::uint32_t maxval, std::vector<std::uint8_t>& rgba) {
  for (std::size_t i = 0; i < rgba.size() / 4 * 3; ++i)
    rgba[i + i / 3] = to_8bit(cursor.number("sample", 0, maxval), maxval);
  cursor.skip_blanks();
  if (!cursor.at_end()) cursor.fail("extra data after the last sample");
}

// Checked before allocating, so a tiny file cannot ask for an absurd buffer: a binary raster has
// an exact size, and a plain one needs at least one byte per sample.
void check_raster_size(PpmCursor& cursor, bool binary, std::uint32_t maxval,
                       std::uint64_t samples) {
  const std::uint64_t sample_bytes = maxval > 255 ? 2 : 1;
  const auto needed = image_detail::checked_mul(samples, binary ? sample_bytes : 1);
  const std::uint64_t remaining = cursor.remaining();
  if (!needed || remaining < *needed)
    cursor.fail("the header needs " + (needed ? std::to_string(*needed) : std::string("too many")) +
                " bytes of samples but " + std::to_string(remaining) + " follow (truncated)");
  if (binary && remaining > *needed) cursor.fail("extra data after the last sample");
}

}  // namespace

Rgba8Image read_ppm(const std::string& path) {
  const std::vector<std::uint8_t> bytes = image_detail::read_file_bytes(path);
  PpmCursor cursor(bytes, path);
  const bool binary = cursor.magic();
  Rgba8Image image;
  image.width = static_cast<int>(cursor.number("width", 1, INT_MAX));
  image.height = static_cast<int>(cursor.number("height", 1, INT_MAX));
  const std::uint32_t maxval = cursor.number("maxval", 1, 65535);
  if (binary) cursor.header_end();
  const std::uint64_t samples = 3 * std::uint64_t(image.width) * std::uint64_t(image.height);
  check_raster_size(cursor, binary, maxval, samples);
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(samples / 3 * 4), 255);
  binary ? read_binary_samples(cursor, maxval, rgba) : read_plain_samples(cursor, maxval, rgba);
  image.frames.push_back(std::move(rgba));
  return image;
}

}  // namespace clrt
