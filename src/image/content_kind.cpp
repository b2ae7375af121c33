#include "image/content_kind.hpp"

#include <cstring>
#include <iterator>
#include <optional>

namespace clrt::image_detail {
namespace {

struct Signature {
  const char* kind;
  std::size_t offset;
  const char* bytes;
  std::size_t size;
  std::optional<ImageFormat> format;  // when clrt reads it
};

// Magic numbers as the formats' specifications give them. Netpbm's are followed by whitespace
// (checked below), since "P6" alone begins ordinary text too.
const Signature kSignatures[] = {
    {"PNG", 0, "\x89PNG\r\n\x1a\n", 8, ImageFormat::Png},
    {"OpenEXR", 0, "\x76\x2f\x31\x01", 4, ImageFormat::Exr},
    {"FSF", 0, "\x3f\x02\x00\x00", 4, ImageFormat::Fsf},
    {"FSF", 0, "\x00\x00\x02\x3f", 4, ImageFormat::Fsf},
    {"JPEG", 0, "\xff\xd8\xff", 3, std::nullopt},
    {"GIF", 0, "GIF87a", 6, std::nullopt},
    {"GIF", 0, "GIF89a", 6, std::nullopt},
    {"TIFF", 0, "II*\0", 4, std::nullopt},
    {"TIFF", 0, "MM\0*", 4, std::nullopt},
    {"WebP", 8, "WEBP", 4, std::nullopt},
    {"Radiance HDR", 0, "#?RADIANCE", 10, std::nullopt},
    {"Radiance HDR", 0, "#?RGBE", 6, std::nullopt},
    {"QOI", 0, "qoif", 4, std::nullopt},
    {"Photoshop", 0, "8BPS", 4, std::nullopt},
    {"JPEG 2000", 0, "\0\0\0\x0cjP  ", 8, std::nullopt},
    {"AVIF", 4, "ftypavif", 8, std::nullopt},
    {"HEIF", 4, "ftypheic", 8, std::nullopt},
    {"DDS", 0, "DDS ", 4, std::nullopt},
    {"BMP", 0, "BM", 2, std::nullopt},
    {"PPM", 0, "P6", 2, ImageFormat::Ppm},
    {"PPM", 0, "P3", 2, ImageFormat::Ppm},
    {"PFM", 0, "PF", 2, ImageFormat::Pfm},
    {"PFM", 0, "Pf", 2, ImageFormat::Pfm},
    {"PGM", 0, "P5", 2, std::nullopt},
    {"PGM", 0, "P2", 2, std::nullopt},
    {"PBM", 0, "P4", 2, std::nullopt},
    {"PBM", 0, "P1", 2, std::nullopt},
    {"PAM", 0, "P7", 2, std::nullopt},
};

bool matches(const Signature& s, ByteSpan head) {
  if (head.size() < s.offset + s.size || std::memcmp(head.data() + s.offset, s.bytes, s.size) != 0)
    return false;
  if (s.bytes[0] == 'P' && s.size == 2) {  // Netpbm: whitespace or a comment follows
    if (head.size() < 3) return false;
    const std::uint8_t next = head[2];
    return next == ' ' || next == '\t' || next == '\n' || next == '\r' || next == '#';
  }
  if (std::strcmp(s.kind, "WebP") == 0) return std::memcmp(head.data(), "RIFF", 4) == 0;
  // BMP's two reserved 16-bit fields (bytes 6 to 9) are zero; "BM" alone starts words too.
  if (std::strcmp(s.kind, "BMP") == 0)
    return head.size() >= 10 && head[6] == 0 && head[7] == 0 && head[8] == 0 && head[9] == 0;
  return true;
}

const Signature* find_signature(ByteSpan head) {
  for (const Signature& s : kSignatures)
    if (matches(s, head)) return &s;
  return nullptr;
}

std::string upper_name(ImageFormat format) {
  std::string name = format_name(format);
  for (char& c : name) c = static_cast<char>(c - 'a' + 'A');
  return name == "EXR" ? "OpenEXR" : name;
}

std::string with_article(const std::string& kind) {
  // "an" before a vowel sound: OpenEXR, AVIF, and FSF spelt out ("ef-es-ef").
  const bool vowel = std::strchr("AEIOU", kind[0]) || kind == "FSF";
  return (vowel ? "an " : "a ") + kind;
}

}  // namespace

std::string content_kind(ByteSpan head) {
  const Signature* s = find_signature(head);
  return s ? s->kind : "";
}

void check_content(ByteSpan head, ImageFormat format, const std::string& name) {
  const Signature* s = find_signature(head);
  if (!s || s->format == format) return;
  const std::string start =
      name + ": the name says " + upper_name(format) + ", but the file holds " + with_article(s->kind) + " image; ";
  if (s->format)
    throw ImageError(start + "name it ." + format_name(*s->format) + " to read it as one");
  throw ImageError(start + "clrt reads FSF, PNG, PPM, PFM and OpenEXR images, so convert it to one of those");
}

}  // namespace clrt::image_detail
