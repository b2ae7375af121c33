#include <climits>
#include <cstdio>

#include "image/byte_order.hpp"
#include "image/checked_size.hpp"
#include "image/content_kind.hpp"
#include "image/decoders.hpp"
#include "image/fsf_layout.hpp"
#include "image/image_checks.hpp"

namespace clrt {
namespace {

using image_detail::kFsfHeaderBytes;
using image_detail::kFsfMagic;

std::string hex_bytes(const std::uint8_t* bytes, int count) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    char byte[4];
    std::snprintf(byte, sizeof byte, "%02x", bytes[i]);
    text += (i == 0 ? "" : " ") + std::string(byte);
  }
  return text;
}

std::string describe_size(const FsfHeader& header) {
  return std::to_string(header.width) + "x" + std::to_string(header.height) + ", " +
         std::to_string(header.frames) + " frame(s)";
}

FsfHeader parse_header(const std::uint8_t* raw, const std::string& path) {
  FsfHeader header;
  if (image_detail::load_u32_le(raw) != kFsfMagic) {
    image_detail::check_content(ByteSpan(raw, kFsfHeaderBytes), ImageFormat::Fsf, path);
    if (image_detail::load_u32_be(raw) != kFsfMagic)
      throw ImageError(path + ": not an FSF file: it starts with " + hex_bytes(raw, 4) +
                       ", not the magic number 575 in either byte order");
    header.big_endian = true;
  }
  const auto field = [&](int index) {
    const std::uint8_t* bytes = raw + 4 * index;
    return header.big_endian ? image_detail::load_u32_be(bytes) : image_detail::load_u32_le(bytes);
  };
  header.width = field(1);
  header.height = field(2);
  header.frames = field(3);
  return header;
}

// The header's file size, or nothing when it overflows 64 bits.
std::optional<std::uint64_t> file_bytes_for(const FsfHeader& header) {
  const auto pixels = image_detail::checked_mul(header.width, header.height);
  const auto frame_bytes = pixels ? image_detail::checked_mul(*pixels, 4) : std::nullopt;
  const auto all_frames =
      frame_bytes ? image_detail::checked_mul(*frame_bytes, header.frames) : std::nullopt;
  if (!all_frames || *all_frames > UINT64_MAX - kFsfHeaderBytes) return std::nullopt;
  return *all_frames + kFsfHeaderBytes;
}

void check_sizes(const FsfHeader& header, std::uint64_t file_bytes, const std::string& path) {
  if (header.width == 0 || header.height == 0 || header.frames == 0)
    throw ImageError(path + ": invalid FSF header: " + describe_size(header) +
                     "; none may be zero");
  if (header.width > INT_MAX || header.height > INT_MAX)
    throw ImageError(path + ": invalid FSF header: " + describe_size(header) + " is too large");
  image_detail::check_declared_size(header.width, header.height, path, "FSF");
  const auto expected = file_bytes_for(header);
  if (expected == file_bytes) return;
  const std::string described =
      expected ? std::to_string(*expected) + " bytes" : "more than 2^64 bytes";
  throw ImageError(path + ": the FSF header describes " + describe_size(header) + ", " + described +
                   ", but the file has " + std::to_string(file_bytes) +
                   (!expected || file_bytes < *expected ? " (truncated)"
                                                        : " (extra data after the last frame)"));
}

}  // namespace

std::uint64_t fsf_file_size(const FsfHeader& header) {
  const auto bytes = file_bytes_for(header);
  if (!bytes)
    throw ImageError("an FSF file of " + describe_size(header) + " would exceed 2^64 bytes");
  return *bytes;
}

FsfHeader image_detail::checked_fsf_header(ByteSpan head, std::uint64_t file_bytes,
                                           const std::string& name) {
  if (head.size() < kFsfHeaderBytes) {
    check_content(head, ImageFormat::Fsf, name);
    throw ImageError(name + ": not an FSF file: " + std::to_string(file_bytes) +
                     " bytes, shorter than the 16-byte header");
  }
  const FsfHeader header = parse_header(head.data(), name);
  check_sizes(header, file_bytes, name);
  return header;
}

FsfHeader image_detail::read_checked_fsf_header(InputFile& file) {
  std::uint8_t raw[kFsfHeaderBytes];
  const std::size_t got = file.size() < kFsfHeaderBytes ? static_cast<std::size_t>(file.size()) : kFsfHeaderBytes;
  file.read_exact(raw, got);
  return checked_fsf_header(ByteSpan(raw, got), file.size(), file.path());
}

FsfHeader read_fsf_header(const std::string& path) {
  image_detail::InputFile file(path);
  return image_detail::read_checked_fsf_header(file);
}

ImageInfo image_detail::fsf_header_info(const FsfHeader& header) {
  ImageInfo info = basic_info(ImageFormat::Fsf, static_cast<int>(header.width),
                              static_cast<int>(header.height), "RGBA", "8-bit");
  info.frames = header.frames;
  info.details = {{"byte order", header.big_endian ? "big-endian" : "little-endian"},
                  {"bytes", std::to_string(fsf_file_size(header))}};
  return info;
}

}  // namespace clrt
