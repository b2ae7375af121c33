// Reading the text headers of PPM and PFM: decimal numbers and words separated by whitespace and
// '#' comments, then one whitespace character, then a raster whose size the header fixes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/byte_span.hpp"

namespace clrt::image_detail {

class NetpbmCursor {
 public:
  // `kind` ("PPM", "PFM") goes into every error: "<path>: not a readable <kind>: ...".
  NetpbmCursor(ByteSpan bytes, const char* kind, const std::string& path)
      : bytes_(bytes), kind_(kind), path_(path) {}

  [[noreturn]] void fail(const std::string& what) const;

  // "P" and then one of `letters`, followed by whitespace; returns that letter.
  char magic(const char* letters);
  // Blanks are skipped first; a number may not exceed `max`.
  std::uint32_t number(const char* name, std::uint32_t min, std::uint32_t max);
  // The next run of non-whitespace characters, blanks skipped first.
  std::string word(const char* name);
  void skip_blanks();
  // The header's width and height, refused beyond what clrt reads before anything is allocated.
  void check_size(std::int64_t width, std::int64_t height) const;
  // The single whitespace character that ends a binary header.
  void header_end();
  // Checked before allocating, so a tiny file cannot ask for an absurd buffer: at least `needed`
  // bytes must follow (nothing: more than 2^64), and exactly that many when `exact`.
  void expect_raster(std::optional<std::uint64_t> needed, bool exact);

  bool at_end() const { return pos_ >= bytes_.size(); }
  const std::uint8_t* here() const { return bytes_.data() + pos_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }

 private:
  ByteSpan bytes_;
  const char* kind_;
  const std::string& path_;
  std::size_t pos_ = 0;
};

}  // namespace clrt::image_detail
