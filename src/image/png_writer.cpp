// PNG written by clrt itself around zlib, not through libpng: libpng compresses a stream on one
// thread, and at 1920x1080 that alone was 20 ms, against a target of 5% of the whole command
// (docs/images.md, "Choosing the PNG encoder"). The chunks are few and simple; libpng still
// reads every PNG, and the tests read what this writes with it.
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "image/byte_order.hpp"
#include "image/encoders.hpp"
#include "image/placement.hpp"
#include "image/png_bands.hpp"

namespace clrt::image_detail {
namespace {

constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::uint8_t kColourRgb = 2, kColourRgba = 6;
constexpr std::uint8_t kSrgbPerceptual = 0;
// PNG limits a chunk to 2^31 - 1 bytes; a band larger than this goes into several IDATs.
constexpr std::size_t kMaxChunkBytes = std::size_t{1} << 30;

void write_chunk(ByteSink& sink, const char (&type)[5], const std::uint8_t* data,
                 std::size_t size) {
  std::vector<std::uint8_t> head;
  append_u32_be(head, static_cast<std::uint32_t>(size));
  head.insert(head.end(), type, type + 4);
  uLong crc = crc32(0, head.data() + 4, 4);
  if (size > 0) crc = crc32_z(crc, data, size);  // a null buffer would restart the CRC
  std::vector<std::uint8_t> tail;
  append_u32_be(tail, static_cast<std::uint32_t>(crc));
  sink.write(head.data(), head.size());
  if (size > 0) sink.write(data, size);
  sink.write(tail.data(), tail.size());
}

void write_chunk(ByteSink& sink, const char (&type)[5], const std::vector<std::uint8_t>& data) {
  write_chunk(sink, type, data.data(), data.size());
}

std::vector<std::uint8_t> header(const EightBitRows& rows, bool rgba) {
  std::vector<std::uint8_t> ihdr;
  append_u32_be(ihdr, static_cast<std::uint32_t>(rows.width()));
  append_u32_be(ihdr, static_cast<std::uint32_t>(rows.height()));
  // 8-bit samples; deflate compression, adaptive filtering (PNG's only methods), no interlace.
  ihdr.insert(ihdr.end(), {8, rgba ? kColourRgba : kColourRgb, 0, 0, 0});
  return ihdr;
}

}  // namespace

void check_png_encoding(const PngEncoding& encoding) {
  if (encoding.level < 0 || encoding.level > 9)
    throw ImageError("PNG compression level " + std::to_string(encoding.level) +
                     " is outside 0-9");
}

// An opaque frame (everything clrt renders) is stored as RGB: a quarter smaller, same pixels.
// The sRGB chunk says the samples are display values, as the contract's quantisation makes them.
// A placement and a stopped render's sample count go into tEXt chunks before the image data.
void encode_png(const EightBitRows& rows, const PngEncoding& encoding, ByteSink& sink,
                const std::string& samples) {
  // The keyword, its terminating NUL as the separator, the text.
  const auto write_text = [&sink](const char* key, const std::string& text) {
    std::vector<std::uint8_t> chunk(key, key + std::strlen(key) + 1);
    chunk.insert(chunk.end(), text.begin(), text.end());
    write_chunk(sink, "tEXt", chunk);
  };
  const bool rgba = !rows.opaque();
  sink.write(kSignature, sizeof kSignature);
  write_chunk(sink, "IHDR", header(rows, rgba));
  write_chunk(sink, "sRGB", {kSrgbPerceptual});
  if (const auto placement = recorded_placement(rows.placement(), rows.width(), rows.height()))
    write_text(kPngPlacementKey, placement_text(*placement, rows.width(), rows.height()));
  if (!samples.empty()) write_text(kSamplesKey, samples);
  compress_png_rows(rows, rgba, encoding, [&](const std::uint8_t* data, std::size_t size) {
    for (std::size_t start = 0; start < size; start += kMaxChunkBytes)
      write_chunk(sink, "IDAT", data + start, std::min(kMaxChunkBytes, size - start));
  });
  write_chunk(sink, "IEND", nullptr, 0);
}

}  // namespace clrt::image_detail
