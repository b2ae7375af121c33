// PFM: "PF" (RGB) or "Pf" (grey), width, height, then the scale: its sign gives the byte order
// (negative: little-endian) and its magnitude multiplies every value, as PFM readers commonly
// do. Then one whitespace character and exactly width * height pixels of 32-bit floats, rows
// from the bottom up.
#include <charconv>
#include <climits>
#include <cmath>

#include "image/byte_order.hpp"
#include "image/checked_size.hpp"
#include "image/decoders.hpp"
#include "image/netpbm_cursor.hpp"

namespace clrt {
namespace {

using image_detail::NetpbmCursor;

struct PfmHeader {
  std::size_t channels = 3;
  int width = 0, height = 0;
  std::string scale_text;
  float scale = -1.0f;
};

PfmHeader read_pfm_header(NetpbmCursor& cursor) {
  PfmHeader header;
  header.channels = cursor.magic("Ff") == 'F' ? 3 : 1;
  header.width = static_cast<int>(cursor.number("width", 1, INT_MAX));
  header.height = static_cast<int>(cursor.number("height", 1, INT_MAX));
  cursor.check_size(header.width, header.height);
  header.scale_text = cursor.word("scale");
  const char* end = header.scale_text.data() + header.scale_text.size();
  const auto parsed = std::from_chars(header.scale_text.data(), end, header.scale);
  if (parsed.ec != std::errc() || parsed.ptr != end || !std::isfinite(header.scale) ||
      header.scale == 0.0f)
    cursor.fail("the scale \"" + header.scale_text + "\" is not a finite non-zero number");
  cursor.header_end();
  const auto pixels =
      image_detail::checked_mul(std::uint64_t(header.width), std::uint64_t(header.height));
  cursor.expect_raster(pixels ? image_detail::checked_mul(*pixels, 4 * header.channels)
                              : std::nullopt,
                       true);
  return header;
}

}  // namespace

FloatImage image_detail::pfm_pixels(const ImageBytes& file) {
  NetpbmCursor cursor(file.bytes, "PFM", file.name);
  const PfmHeader header = read_pfm_header(cursor);
  const bool little_endian = header.scale < 0.0f;
  const float magnitude = std::fabs(header.scale);
  const std::size_t width = static_cast<std::size_t>(header.width);
  const std::size_t height = static_cast<std::size_t>(header.height);
  std::vector<float> rgb(3 * width * height);
  const std::uint8_t* in = cursor.here();
  for (std::size_t file_row = 0; file_row < height; ++file_row) {
    float* out = rgb.data() + 3 * width * (height - 1 - file_row);
    for (std::size_t x = 0; x < width; ++x)
      for (std::size_t c = 0; c < 3; ++c) {
        const std::uint8_t* sample = in + 4 * (header.channels * (file_row * width + x) +
                                               (header.channels == 3 ? c : 0));
        const float value = image_detail::float_from_bits(little_endian
                                                              ? image_detail::load_u32_le(sample)
                                                              : image_detail::load_u32_be(sample));
        // A scale of 1 leaves the file's bits alone (NaN payloads included).
        out[3 * x + c] = magnitude == 1.0f ? value : value * magnitude;
      }
  }
  return FloatImage(header.width, header.height, std::move(rgb));
}

ImageInfo image_detail::pfm_info(const ImageBytes& file) {
  NetpbmCursor cursor(file.bytes, "PFM", file.name);
  const PfmHeader header = read_pfm_header(cursor);
  ImageInfo info = basic_info(ImageFormat::Pfm, header.width, header.height,
                              header.channels == 3 ? "RGB" : "grey", "32-bit float");
  info.float32 = true;
  info.details = {{"byte order", header.scale < 0.0f ? "little-endian" : "big-endian"},
                  {"scale", header.scale_text}};
  return info;
}

}  // namespace clrt
