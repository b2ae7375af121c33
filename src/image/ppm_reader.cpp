// PPM as Netpbm defines it: "P6" (binary) or "P3" (plain), width, height and maxval as decimal
// numbers separated by whitespace and '#' comments, one whitespace character, then the samples
// (binary: one byte each, two big-endian bytes when maxval > 255). One image per file: trailing
// bytes are an error, as a truncated raster is.
#include <climits>

#include "image/checked_size.hpp"
#include "image/decoders.hpp"
#include "image/netpbm_cursor.hpp"

namespace clrt {
namespace {

using image_detail::NetpbmCursor;

struct PpmHeader {
  bool binary = true;
  int width = 0, height = 0;
  std::uint32_t maxval = 255;
};

// Leaves the cursor at the first sample, the raster's size checked.
PpmHeader read_ppm_header(NetpbmCursor& cursor) {
  PpmHeader header;
  header.binary = cursor.magic("63") == '6';
  header.width = static_cast<int>(cursor.number("width", 1, INT_MAX));
  header.height = static_cast<int>(cursor.number("height", 1, INT_MAX));
  cursor.check_size(header.width, header.height);
  header.maxval = cursor.number("maxval", 1, 65535);
  if (header.binary) cursor.header_end();
  // A plain raster needs at least one byte per sample.
  const std::uint64_t samples = 3 * std::uint64_t(header.width) * std::uint64_t(header.height);
  const std::uint64_t sample_bytes = header.binary && header.maxval > 255 ? 2 : 1;
  cursor.expect_raster(image_detail::checked_mul(samples, sample_bytes), header.binary);
  return header;
}

std::uint8_t to_8bit(std::uint32_t sample, std::uint32_t maxval) {
  return static_cast<std::uint8_t>((sample * 255u + maxval / 2) / maxval);
}

// Sample i of the file (R, G, B of pixel i / 3) goes to byte i + i / 3 of the RGBA frame.
void read_binary_samples(NetpbmCursor& cursor, std::uint32_t maxval,
                         std::vector<std::uint8_t>& rgba) {
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

void read_plain_samples(NetpbmCursor& cursor, std::uint32_t maxval,
                        std::vector<std::uint8_t>& rgba) {
  for (std::size_t i = 0; i < rgba.size() / 4 * 3; ++i)
    rgba[i + i / 3] = to_8bit(cursor.number("sample", 0, maxval), maxval);
  cursor.skip_blanks();
  if (!cursor.at_end()) cursor.fail("extra data after the last sample");
}

}  // namespace

Rgba8Image image_detail::ppm_pixels(const ImageBytes& file) {
  NetpbmCursor cursor(file.bytes, "PPM", file.name);
  const PpmHeader header = read_ppm_header(cursor);
  std::vector<std::uint8_t> rgba(4 * std::size_t(header.width) * std::size_t(header.height), 255);
  header.binary ? read_binary_samples(cursor, header.maxval, rgba)
                : read_plain_samples(cursor, header.maxval, rgba);
  return Rgba8Image(header.width, header.height, {std::move(rgba)});
}

ImageInfo image_detail::ppm_info(const ImageBytes& file) {
  NetpbmCursor cursor(file.bytes, "PPM", file.name);
  const PpmHeader header = read_ppm_header(cursor);
  ImageInfo info = basic_info(ImageFormat::Ppm, header.width, header.height, "RGB",
                              header.maxval > 255 ? "16-bit" : "8-bit");
  info.details = {{"encoding", header.binary ? "binary (P6)" : "plain text (P3)"},
                  {"maxval", std::to_string(header.maxval)}};
  return info;
}

}  // namespace clrt
