// Fixed-width integers and floats in an explicit byte order, independent of the host's.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace clrt::image_detail {

inline std::uint32_t load_u32_le(const std::uint8_t* bytes) {
  return std::uint32_t{bytes[0]} | std::uint32_t{bytes[1]} << 8 | std::uint32_t{bytes[2]} << 16 |
         std::uint32_t{bytes[3]} << 24;
}

inline std::uint32_t load_u32_be(const std::uint8_t* bytes) {
  return std::uint32_t{bytes[3]} | std::uint32_t{bytes[2]} << 8 | std::uint32_t{bytes[1]} << 16 |
         std::uint32_t{bytes[0]} << 24;
}

inline void append_u32_le(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<std::uint8_t>(value >> shift));
}

inline void append_u32_be(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<std::uint8_t>(value >> shift));
}

// Shifts, not memcpy, so the order is the same on every host; compilers make it one store on a
// little-endian one.
inline void store_u32_le(std::uint8_t* out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

inline std::uint32_t float_bits(float value) {
  static_assert(sizeof(float) == sizeof(std::uint32_t), "PFM needs 32-bit IEEE floats");
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

inline float float_from_bits(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace clrt::image_detail
