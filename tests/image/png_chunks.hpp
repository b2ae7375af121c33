// PNG files put together chunk by chunk, for the tests of what the readers refuse.
#pragma once

#include <cstdint>
#include <string>

#include "test_files.hpp"

namespace clrt::test {

// CRC-32 as PNG defines it (ISO 3309, reflected 0xedb88320), bit by bit.
inline std::uint32_t png_crc(const Bytes& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (std::uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = crc & 1 ? (crc >> 1) ^ 0xedb88320u : crc >> 1;
  }
  return crc ^ 0xffffffffu;
}

inline Bytes u32_be(std::uint32_t v) {
  return {Bytes::value_type(v >> 24), Bytes::value_type(v >> 16), Bytes::value_type(v >> 8),
          Bytes::value_type(v)};
}

// Length, type, data and CRC.
inline Bytes png_chunk(const std::string& type, const Bytes& data) {
  const Bytes body = concat({bytes_of(type), data});
  return concat({u32_be(static_cast<std::uint32_t>(data.size())), body, u32_be(png_crc(body))});
}

inline Bytes text_chunk(const std::string& key, const std::string& text) {
  return png_chunk("tEXt", concat({bytes_of(key), {0}, bytes_of(text)}));
}

// An 8-bit RGBA PNG whose IHDR declares width x height, with `chunks` after it and image data
// of a few bytes that no decoder gets far into.
inline Bytes png_declaring(std::uint32_t width, std::uint32_t height, const Bytes& chunks = {}) {
  const Bytes signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const Bytes ihdr = concat({u32_be(width), u32_be(height), {8, 6, 0, 0, 0}});
  return concat({signature, png_chunk("IHDR", ihdr), chunks,
                 png_chunk("IDAT", {0x78, 0x9c, 0x03, 0x00}), png_chunk("IEND", {})});
}

}  // namespace clrt::test
