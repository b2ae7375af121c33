// FNV-1a, 64 bits, from a chosen basis (two bases give two independent hashes of one text),
// and a hash as the 16 hex digits files and messages show.
#pragma once

#include <cstdint>
#include <string>

namespace clrt {

constexpr std::uint64_t kFnv1aBasis = 0xcbf29ce484222325ull;

inline std::uint64_t fnv1a(const std::string& text, std::uint64_t basis = kFnv1aBasis) {
  std::uint64_t h = basis;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

inline std::string hex(std::uint64_t value) {
  static const char* const digits = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4) out[static_cast<std::size_t>(i)] = digits[value & 15u];
  return out;
}

}  // namespace clrt
