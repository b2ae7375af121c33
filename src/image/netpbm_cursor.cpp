#include "image/netpbm_cursor.hpp"

#include <cctype>
#include <cstring>

#include "image/image.hpp"
#include "image/image_checks.hpp"

namespace clrt::image_detail {

void NetpbmCursor::check_size(std::int64_t width, std::int64_t height) const {
  check_declared_size(width, height, path_, kind_);
}

void NetpbmCursor::fail(const std::string& what) const {
  throw ImageError(path_ + ": not a readable " + kind_ + ": " + what + " (at byte " +
                   std::to_string(pos_) + ")");
}

char NetpbmCursor::magic(const char* letters) {
  if (bytes_.size() < 3 || bytes_[0] != 'P' || !std::strchr(letters, bytes_[1]) ||
      bytes_[1] == 0 || !(std::isspace(bytes_[2]) || bytes_[2] == '#'))
    fail(std::string("it does not start with P") + letters[0] + " or P" + letters[1]);
  pos_ = 2;
  return static_cast<char>(bytes_[1]);
}

std::uint32_t NetpbmCursor::number(const char* name, std::uint32_t min, std::uint32_t max) {
  skip_blanks();
  if (at_end() || !std::isdigit(bytes_[pos_])) fail(std::string("expected the ") + name);
  std::uint64_t value = 0;
  while (!at_end() && std::isdigit(bytes_[pos_])) {
    value = value * 10 + static_cast<std::uint64_t>(bytes_[pos_++] - '0');
    if (value > max) fail(std::string("the ") + name + " exceeds " + std::to_string(max));
  }
  if (value < min) fail(std::string("the ") + name + " is below " + std::to_string(min));
  return static_cast<std::uint32_t>(value);
}

std::string NetpbmCursor::word(const char* name) {
  skip_blanks();
  const std::size_t start = pos_;
  while (!at_end() && !std::isspace(bytes_[pos_])) ++pos_;
  if (pos_ == start) fail(std::string("expected the ") + name);
  return std::string(bytes_.begin() + static_cast<std::ptrdiff_t>(start),
                     bytes_.begin() + static_cast<std::ptrdiff_t>(pos_));
}

void NetpbmCursor::skip_blanks() {
  while (!at_end()) {
    if (bytes_[pos_] == '#') {
      while (!at_end() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
    } else if (std::isspace(bytes_[pos_])) {
      ++pos_;
    } else {
      return;
    }
  }
}

void NetpbmCursor::header_end() {
  if (at_end() || !std::isspace(bytes_[pos_])) fail("expected one whitespace after the header");
  ++pos_;
}

void NetpbmCursor::expect_raster(std::optional<std::uint64_t> needed, bool exact) {
  const std::uint64_t left = remaining();
  if (!needed || left < *needed)
    fail("the header needs " + (needed ? std::to_string(*needed) : std::string("too many")) +
         " bytes of samples but " + std::to_string(left) + " follow (truncated)");
  if (exact && left > *needed) fail("extra data after the last sample");
}

}  // namespace clrt::image_detail
