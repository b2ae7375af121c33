#include "scene/scene_text_check.hpp"

#include <array>
#include <cstdio>

#include "scene/source_location.hpp"

namespace clrt {
namespace {

struct KnownFormat {
  std::string_view magic;
  const char* name;
};

// Formats a user may hand clrt by mistake: its own outputs and what travels with scenes.
constexpr std::array<KnownFormat, 9> kKnownFormats{{
    {"\x89PNG\r\n\x1a\n", "a PNG image"},
    {"\x76\x2f\x31\x01", "an OpenEXR image"},
    {std::string_view("\x3f\x02\x00\x00", 4), "an FSF image"},
    {std::string_view("\x00\x00\x02\x3f", 4), "an FSF image"},
    {"\x1f\x8b", "a gzip archive"},
    {"\xff\xd8\xff", "a JPEG image"},
    {"PK\x03\x04", "a zip archive"},
    {"\x7f" "ELF", "a program"},
    {"GIF8", "a GIF image"},
}};

// The length of the UTF-8 sequence that starts at `at`, or 0 when it is not one (overlong
// forms, surrogates and code points past U+10FFFF included).
std::size_t utf8_sequence_length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  std::size_t length = 0;
  unsigned char second_min = 0x80, second_max = 0xbf;
  if (lead >= 0xc2 && lead <= 0xdf) length = 2;
  else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    if (lead == 0xe0) second_min = 0xa0;
    if (lead == 0xed) second_max = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    if (lead == 0xf0) second_min = 0x90;
    if (lead == 0xf4) second_max = 0x8f;
  } else
    return 0;
  if (at + length > text.size()) return 0;
  if (byte(at + 1) < second_min || byte(at + 1) > second_max) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (byte(at + i) < 0x80 || byte(at + i) > 0xbf) return 0;
  return length;
}

[[noreturn]] void refuse_byte(const std::string& path, std::string_view text, std::size_t at) {
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < at; ++i)
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned char>(text[at]));
  const std::string what = text[at] == '\0' ? "a NUL byte" : std::string("the byte ") + hex;
  throw SceneError({path, line, static_cast<int>(at - line_start) + 1},
                   what + ", which is not UTF-8 text: this is not a scene file");
}

}  // namespace

void check_scene_is_text(const std::string& path, std::string_view text) {
  for (const KnownFormat& format : kKnownFormats)
    if (text.substr(0, format.magic.size()) == format.magic)
      throw SceneError(SourceLocation::whole_file(path),
                       std::string("this is ") + format.name + ", not a scene");
  for (std::size_t at = 0; at < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[at]);
    if (c != 0 && c < 0x80) {
      ++at;
      continue;
    }
    const std::size_t length = c == 0 ? 0 : utf8_sequence_length(text, at);
    if (length == 0) refuse_byte(path, text, at);
    at += length;
  }
}

}  // namespace clrt
