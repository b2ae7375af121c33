// How the PNG writer compresses: PNG's row filters and zlib's level and strategy. Every setting
// stores the same pixels; they trade encoding time against file size. The default is the one
// chosen by measurement (docs/images.md, "Choosing the PNG encoder").
#pragma once

#include <string>

namespace clrt {

// The filter applied to every row before compression (PNG's five filter types), or Adaptive:
// all five are tried on each row and the one that looks most compressible is kept.
enum class PngFilters { None, Sub, Up, Average, Paeth, Adaptive };

// zlib's strategy: Default (LZ77 matches and Huffman codes), Filtered (favours Huffman codes on
// the small values filters produce; libpng's choice when rows are filtered), Rle (matches only
// at distance 1: runs), HuffmanOnly (no matches at all).
enum class PngStrategy { Default, Filtered, Rle, HuffmanOnly };

struct PngEncoding {
  int level = 1;  // zlib's 0 (stored, no compression) to 9 (smallest, slowest)
  PngFilters filters = PngFilters::Sub;
  PngStrategy strategy = PngStrategy::Rle;

  bool operator==(const PngEncoding& other) const {
    return level == other.level && filters == other.filters && strategy == other.strategy;
  }
};

// libpng's and zlib's defaults, which clrt wrote with before it chose its own: 4.5 times slower
// to encode, files 17% smaller.
constexpr PngEncoding kPngLibraryDefaults{6, PngFilters::Adaptive, PngStrategy::Filtered};

// Names as the benchmarks print and take them: "none", "sub", "up", "average", "paeth",
// "adaptive"; "default", "filtered", "rle", "huffman". The parsers throw ImageError naming
// every accepted name.
std::string png_filters_name(PngFilters filters);
std::string png_strategy_name(PngStrategy strategy);
PngFilters png_filters_from_name(const std::string& name);
PngStrategy png_strategy_from_name(const std::string& name);
// "level 1, filters sub, strategy rle"
std::string describe(const PngEncoding& encoding);

}  // namespace clrt
