// PNG's row filters (the PNG specification, section 9): each row is stored as one filter-type
// byte and the row's bytes predicted from their left, upper and upper-left neighbours.
#pragma once

#include <cstddef>
#include <cstdint>

#include "image/png_encoding.hpp"

namespace clrt::image_detail {

// Writes 1 + row_bytes bytes to `out`: the type byte, then `row` filtered. `previous` is the row
// above, or a row of zeros for the image's first row (PNG predicts from zeros there).
// `bytes_per_pixel` is 3 (RGB) or 4 (RGBA). Adaptive tries the five types and keeps the one
// whose output has the smallest sum of magnitudes as signed bytes (libpng's heuristic, which
// the PNG specification recommends).
void filter_row(PngFilters filters, const std::uint8_t* previous, const std::uint8_t* row,
                std::size_t row_bytes, std::size_t bytes_per_pixel, std::uint8_t* out);

}  // namespace clrt::image_detail
