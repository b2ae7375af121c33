// The first bytes of a PNG file, for tests of what a reader refuses from the header alone.
#pragma once

#include <cstdint>
#include <string>

namespace clrt::test {

// A PNG that declares `width` x `height` RGB texels (IHDR) and holds none: an empty IDAT, the
// chunk at which a reader has read the whole header, then IEND.
inline std::string png_header(std::uint32_t width, std::uint32_t height) {
  std::string bytes = "\x89PNG\r\n\x1a\n";
  const auto be32 = [&](std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) bytes.push_back(static_cast<char>((v >> s) & 0xff));
  };
  const auto chunk = [&](const std::string& type, const std::string& data) {
    be32(static_cast<std::uint32_t>(data.size()));
    const std::size_t start = bytes.size();
    bytes += type + data;
    std::uint32_t crc = 0xffffffffu;  // CRC-32 over the type and the data
    for (std::size_t i = start; i < bytes.size(); ++i) {
      crc ^= static_cast<unsigned char>(bytes[i]);
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    be32(~crc);
  };
  std::string header;
  for (std::uint32_t v : {width, height})
    for (int s = 24; s >= 0; s -= 8) header.push_back(static_cast<char>((v >> s) & 0xff));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8-bit RGB, deflate, no interlace
  chunk("IHDR", header);
  chunk("IDAT", "");
  chunk("IEND", "");
  return bytes;
}

}  // namespace clrt::test
