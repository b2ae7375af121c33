#include "image/png_filters.hpp"

#include <cstdlib>

namespace clrt::image_detail {
namespace {

enum FilterType : std::uint8_t { kNone = 0, kSub = 1, kUp = 2, kAverage = 3, kPaeth = 4 };

std::uint8_t paeth_predictor(int left, int up, int up_left) {
  const int estimate = left + up - up_left;
  const int to_left = std::abs(estimate - left), to_up = std::abs(estimate - up),
            to_up_left = std::abs(estimate - up_left);
  if (to_left <= to_up && to_left <= to_up_left) return static_cast<std::uint8_t>(left);
  return static_cast<std::uint8_t>(to_up <= to_up_left ? up : up_left);
}

// Calls emit(i, filtered byte i) for every byte of the row, filtered by `type`. One definition
// of each prediction serves both writing a row and scoring it; the first pixel's bytes have no
// left neighbour and predict from zero.
template <typename Emit>
void predict(FilterType type, const std::uint8_t* up, const std::uint8_t* row, std::size_t n,
             std::size_t bpp, Emit emit) {
  const auto byte = [](int value) { return static_cast<std::uint8_t>(value); };
  switch (type) {
    case kNone:
      for (std::size_t i = 0; i < n; ++i) emit(i, row[i]);
      return;
    case kSub:
      for (std::size_t i = 0; i < bpp; ++i) emit(i, row[i]);
      for (std::size_t i = bpp; i < n; ++i) emit(i, byte(row[i] - row[i - bpp]));
      return;
    case kUp:
      for (std::size_t i = 0; i < n; ++i) emit(i, byte(row[i] - up[i]));
      return;
    case kAverage:
      for (std::size_t i = 0; i < bpp; ++i) emit(i, byte(row[i] - (up[i] >> 1)));
      for (std::size_t i = bpp; i < n; ++i) emit(i, byte(row[i] - ((row[i - bpp] + up[i]) >> 1)));
      return;
    case kPaeth:
      for (std::size_t i = 0; i < bpp; ++i) emit(i, byte(row[i] - up[i]));
      for (std::size_t i = bpp; i < n; ++i)
        emit(i, byte(row[i] - paeth_predictor(row[i - bpp], up[i], up[i - bpp])));
      return;
  }
}

FilterType chosen_type(PngFilters filters, const std::uint8_t* up, const std::uint8_t* row,
                       std::size_t n, std::size_t bpp) {
  switch (filters) {
    case PngFilters::None: return kNone;
    case PngFilters::Sub: return kSub;
    case PngFilters::Up: return kUp;
    case PngFilters::Average: return kAverage;
    case PngFilters::Paeth: return kPaeth;
    case PngFilters::Adaptive: break;
  }
  FilterType best = kNone;
  std::uint64_t best_cost = UINT64_MAX;
  for (const FilterType type : {kNone, kSub, kUp, kAverage, kPaeth}) {
    std::uint64_t cost = 0;
    predict(type, up, row, n, bpp,
            [&](std::size_t, std::uint8_t v) { cost += v < 128 ? v : 256 - v; });
    if (cost < best_cost) {
      best = type;
      best_cost = cost;
    }
  }
  return best;
}

}  // namespace

void filter_row(PngFilters filters, const std::uint8_t* previous, const std::uint8_t* row,
                std::size_t row_bytes, std::size_t bytes_per_pixel, std::uint8_t* out) {
  const FilterType type = chosen_type(filters, previous, row, row_bytes, bytes_per_pixel);
  out[0] = type;
  std::uint8_t* filtered = out + 1;
  predict(type, previous, row, row_bytes, bytes_per_pixel,
          [filtered](std::size_t i, std::uint8_t v) { filtered[i] = v; });
}

}  // namespace clrt::image_detail
