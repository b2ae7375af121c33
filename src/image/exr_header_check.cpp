#include "image/byte_span.hpp"
#include "image/exr_header_check.hpp"

#include <algorithm>
#include <cstring>

#include "image/image.hpp"
#include "image/image_limits.hpp"

namespace clrt::image_detail {
namespace {

// More lines than this share a chunk in no OpenEXR compression (DWAB: 256).
constexpr std::int64_t kMostLinesPerChunk = 256;
// The version field's flags (OpenEXR's file layout): names of up to 255 bytes rather than 31,
// and several parts, each with its header.
constexpr std::uint32_t kLongNames = 0x400;
constexpr std::uint32_t kMultiPart = 0x1000;

// What every OpenEXR header holds (the format's required attributes; OpenEXR writes them all).
// Without them OpenEXR reads on with defaults, and a forged channel then made it ask for 1.8 GB.
const char* const kRequired[] = {"channels",           "compression",      "dataWindow",
                                 "displayWindow",      "lineOrder",        "pixelAspectRatio",
                                 "screenWindowCenter", "screenWindowWidth"};

std::int32_t i32_at(ByteSpan bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | bytes[at + static_cast<std::size_t>(k)];
  std::int32_t out;
  std::memcpy(&out, &v, sizeof out);
  return out;
}

// One part's data window, tiles and channel sampling.
struct Part {
  std::int64_t width = 0, height = 0, tile_width = 0, tile_height = 0;
  std::int64_t x_sampling = 1, y_sampling = 1;  // the largest of any channel
};

// Walks the header as OpenEXR reads it, and refuses what OpenEXR would read differently from its
// declared sizes (a name without its end, a channel list or string vector that runs past its
// attribute) or what would make it allocate more than the file could hold.
class HeaderWalk {
 public:
  HeaderWalk(ByteSpan bytes, const std::string& path)
      : bytes_(bytes), path_(path) {}

  std::vector<Part> parts() {
    if (bytes_.size() < 8) fail("the file ends inside its version field");
    const auto flags = static_cast<std::uint32_t>(i32_at(bytes_, 4));
    longest_name_ = flags & kLongNames ? 255 : 31;
    at_ = 8;
    std::vector<Part> parts;
    do {
      parts.push_back(header());
    } while ((flags & kMultiPart) && !end_of_headers());
    return parts;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw ImageError(path_ + ": not a readable OpenEXR file: " + why);
  }

  // In a multi-part file an empty header (one zero byte) ends the list.
  bool end_of_headers() {
    if (at_ >= bytes_.size()) fail("the file ends inside its headers");
    if (bytes_[at_] != 0) return false;
    ++at_;
    return true;
  }

  // A zero-terminated name of at most `longest_name_` bytes; empty at a header's end.
  std::string name() {
    const std::size_t limit = std::min(bytes_.size(), at_ + longest_name_ + 1);
    const auto begin = bytes_.begin() + static_cast<std::ptrdiff_t>(at_);
    const auto end = std::find(begin, bytes_.begin() + static_cast<std::ptrdiff_t>(limit), 0);
    if (end == bytes_.begin() + static_cast<std::ptrdiff_t>(limit))
      fail(limit == bytes_.size() ? "the file ends inside its header"
                                  : "a name in its header is longer than " +
                                        std::to_string(longest_name_) + " bytes");
    std::string s(begin, end);
    at_ = static_cast<std::size_t>(end - bytes_.begin()) + 1;
    return s;
  }

  Part header() {
    Part part;
    std::vector<std::string> names;
    for (std::string attribute = name(); !attribute.empty(); attribute = name()) {
      const std::string type = name();
      if (at_ + 4 > bytes_.size()) fail("the file ends inside its header");
      const std::int64_t size = i32_at(bytes_, at_);
      at_ += 4;
      if (size < 0 || static_cast<std::uint64_t>(size) > bytes_.size() - at_)
        fail("its attribute '" + attribute + "' declares " + std::to_string(size) +
             " bytes, more than the file has left");
      value(attribute, type, static_cast<std::size_t>(size), part);
      names.push_back(attribute);
      at_ += static_cast<std::size_t>(size);
    }
    for (const char* required : kRequired)
      if (std::find(names.begin(), names.end(), required) == names.end())
        fail(std::string("its header has no '") + required + "' attribute");
    return part;
  }

  // Checks the value of the types whose reading OpenEXR does not bound by the declared size.
  void value(const std::string& attribute, const std::string& type, std::size_t size, Part& part) {
    const std::size_t end = at_ + size;
    if (type == "chlist") {
      channels(attribute, end, part);
    } else if (type == "stringvector") {
      for (std::size_t p = at_; p < end;) {
        const std::int32_t length = p + 4 <= end ? i32_at(bytes_, p) : -1;
        if (length < 0 || static_cast<std::size_t>(length) > end - p - 4)
          fail("a string of its attribute '" + attribute + "' runs past the attribute");
        p += 4 + static_cast<std::size_t>(length);
      }
    } else if (type == "preview") {
      // Width and height (unsigned), then 4 bytes a pixel.
      const std::uint64_t w = size >= 8 ? static_cast<std::uint32_t>(i32_at(bytes_, at_)) : 0;
      const std::uint64_t h = size >= 8 ? static_cast<std::uint32_t>(i32_at(bytes_, at_ + 4)) : 0;
      if (size < 8 || (w != 0 && h > (size - 8) / 4 / w) || 8 + 4 * w * h != size)
        fail("its preview image does not match its attribute's size");
    } else if (attribute == "dataWindow" && type == "box2i" && size == 16) {
      part.width = std::int64_t{i32_at(bytes_, at_ + 8)} - i32_at(bytes_, at_) + 1;
      part.height = std::int64_t{i32_at(bytes_, at_ + 12)} - i32_at(bytes_, at_ + 4) + 1;
    } else if (attribute == "tiles" && type == "tiledesc" && size >= 8) {
      part.tile_width = static_cast<std::uint32_t>(i32_at(bytes_, at_));
      part.tile_height = static_cast<std::uint32_t>(i32_at(bytes_, at_ + 4));
    }
  }

  // Entries of name\0, pixel type, pLinear and 3 reserved bytes, x and y sampling, then \0:
  // OpenEXR reads until the empty name, whatever the declared size says.
  void channels(const std::string& attribute, std::size_t end, Part& part) {
    const std::size_t outer = at_;
    for (;;) {
      const std::string channel = name();
      if (channel.empty()) break;
      if (at_ + 16 > end) fail("its attribute '" + attribute + "' runs past its size");
      const std::int32_t type = i32_at(bytes_, at_);
      const std::int32_t xs = i32_at(bytes_, at_ + 8), ys = i32_at(bytes_, at_ + 12);
      if (type < 0 || type > 2) fail("its channel '" + channel + "' has no pixel type OpenEXR knows");
      if (xs < 1 || ys < 1) fail("its channel '" + channel + "' has a sampling below 1");
      part.x_sampling = std::max<std::int64_t>(part.x_sampling, xs);
      part.y_sampling = std::max<std::int64_t>(part.y_sampling, ys);
      at_ += 16;
    }
    if (at_ != end) fail("its attribute '" + attribute + "' does not end where its size says");
    at_ = outer;
  }

  ByteSpan bytes_;
  const std::string& path_;
  std::size_t at_ = 0;
  std::size_t longest_name_ = 31;
};

void check_part(const Part& part, std::size_t file_bytes, const std::string& path) {
  if (part.width <= 0 || part.height <= 0) return;  // OpenEXR refuses an empty window itself
  if (part.x_sampling > part.width || part.y_sampling > part.height)
    throw ImageError(path + ": not a readable OpenEXR file: a channel's sampling does not fit its " +
                     std::to_string(part.width) + "x" + std::to_string(part.height) + " data window");
  // OpenEXR's decoders allocate whole chunks of lines (16 for ZIP): a forged 6-million-pixel line
  // in a 389-byte file made it ask for 1.1 GB.
  if (!within_image_limits(part.width, part.height))
    throw ImageError(path + ": the OpenEXR data window of " + std::to_string(part.width) + "x" +
                     std::to_string(part.height) + " pixels is larger than clrt reads");
  const std::int64_t chunks =
      part.tile_width > 0 && part.tile_height > 0
          ? ((part.width + part.tile_width - 1) / part.tile_width) *
                ((part.height + part.tile_height - 1) / part.tile_height)
          : (part.height + kMostLinesPerChunk - 1) / kMostLinesPerChunk;
  if (chunks * 8 > static_cast<std::int64_t>(file_bytes))
    throw ImageError(path + ": not a readable OpenEXR file: its data window needs " +
                     std::to_string(chunks) + " chunks, more than its " +
                     std::to_string(file_bytes) + " bytes can hold");
}

}  // namespace

void check_exr_window(ByteSpan bytes, const std::string& path) {
  if (bytes.size() < 4 || i32_at(bytes, 0) != 20000630) return;  // OpenEXR names it itself
  for (const Part& part : HeaderWalk(bytes, path).parts()) check_part(part, bytes.size(), path);
}

}  // namespace clrt::image_detail
