// Byte counts computed from untrusted headers, where a product may not fit in 64 bits.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

namespace clrt::image_detail {

// a * b, or nothing when the product overflows.
inline std::optional<std::uint64_t> checked_mul(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return std::nullopt;
  return a * b;
}

}  // namespace clrt::image_detail
