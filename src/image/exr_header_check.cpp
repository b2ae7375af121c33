#include "image/exr_header_check.hpp"

#include <algorithm>
#include <cstring>
#include <optional>

#include "image/image.hpp"

namespace clrt::image_detail {
namespace {

// More lines than this share a chunk in no OpenEXR compression (DWAB: 256).
constexpr std::int64_t kMostLinesPerChunk = 256;
// As many pixels as clrt renders at most (2^28, scene/limits.hpp), in any image it reads.
constexpr std::int64_t kMostPixels = std::int64_t{1} << 28;

std::int32_t i32_at(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | bytes[at + static_cast<std::size_t>(k)];
  std::int32_t out;
  std::memcpy(&out, &v, sizeof out);
  return out;
}

// What every OpenEXR header holds (the format's required attributes; OpenEXR writes them all).
// Without them OpenEXR reads on with defaults, and a forged channel then made it ask for 1.8 GB.
const char* const kRequired[] = {"channels",         "compression",        "dataWindow",
                                 "displayWindow",    "lineOrder",          "pixelAspectRatio",
                                 "screenWindowCenter", "screenWindowWidth"};

// The data window and, for a tiled file, the tile size, read from the header's attributes:
// name\0 type\0 size(int32) value, until an empty name.
struct Window {
  std::int64_t width = 0, height = 0, tile_width = 0, tile_height = 0;
  // The largest x and y sampling of any channel (a chlist entry: name\0, pixel type, pLinear
  // and 3 reserved bytes, xSampling, ySampling).
  std::int64_t x_sampling = 1, y_sampling = 1;
  std::vector<std::string> names;
};

void read_samplings(const std::vector<std::uint8_t>& bytes, std::size_t at, std::size_t end, Window& w) {
  while (at < end && bytes[at] != 0) {
    const auto name_end = std::find(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                                    bytes.begin() + static_cast<std::ptrdiff_t>(end), 0);
    at = static_cast<std::size_t>(name_end - bytes.begin()) + 1;
    if (at + 16 > end) return;
    const std::int32_t xs = i32_at(bytes, at + 8), ys = i32_at(bytes, at + 12);
    w.x_sampling = xs < 1 ? 0 : std::max<std::int64_t>(w.x_sampling, xs);
    w.y_sampling = ys < 1 ? 0 : std::max<std::int64_t>(w.y_sampling, ys);
    if (xs < 1 || ys < 1) return;
    at += 16;
  }
}

std::optional<Window> read_window(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  Window w;
  bool found = false;
  std::size_t at = 8;  // magic number and version
  const auto word = [&]() -> std::optional<std::string> {
    const auto end = std::find(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.end(), 0);
    if (end == bytes.end()) return std::nullopt;
    std::string s(bytes.begin() + static_cast<std::ptrdiff_t>(at), end);
    at = static_cast<std::size_t>(end - bytes.begin()) + 1;
    return s;
  };
  while (at < bytes.size()) {
    const std::optional<std::string> name = word();
    if (!name) return std::nullopt;
    if (name->empty()) {
      for (const char* required : kRequired)
        if (std::find(w.names.begin(), w.names.end(), required) == w.names.end())
          throw ImageError(path + ": not a readable OpenEXR file: its header has no '" + required +
                           "' attribute");
      return found ? std::optional<Window>(w) : std::nullopt;
    }
    const std::optional<std::string> type = word();
    if (!type || at + 4 > bytes.size()) return std::nullopt;
    const std::int64_t size = i32_at(bytes, at);
    at += 4;
    if (size < 0 || static_cast<std::uint64_t>(size) > bytes.size() - at)
      throw ImageError(path + ": not a readable OpenEXR file: its attribute '" + *name +
                       "' declares " + std::to_string(size) + " bytes, more than the file has left");
    w.names.push_back(*name);
    if (*name == "channels" && *type == "chlist") {
      read_samplings(bytes, at, at + static_cast<std::size_t>(size), w);
    } else if (*name == "dataWindow" && *type == "box2i" && size == 16) {
      w.width = std::int64_t{i32_at(bytes, at + 8)} - i32_at(bytes, at) + 1;
      w.height = std::int64_t{i32_at(bytes, at + 12)} - i32_at(bytes, at + 4) + 1;
      found = true;
    } else if (*name == "tiles" && *type == "tiledesc" && size >= 8) {
      w.tile_width = static_cast<std::uint32_t>(i32_at(bytes, at));
      w.tile_height = static_cast<std::uint32_t>(i32_at(bytes, at + 4));
    }
    at += static_cast<std::size_t>(size);
  }
  return std::nullopt;
}

}  // namespace

void check_exr_window(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  const std::optional<Window> w = read_window(bytes, path);
  if (!w || w->width <= 0 || w->height <= 0) return;
  if (w->x_sampling < 1 || w->y_sampling < 1 || w->x_sampling > w->width || w->y_sampling > w->height)
    throw ImageError(path + ": not a readable OpenEXR file: a channel's sampling does not fit its " +
                     std::to_string(w->width) + "x" + std::to_string(w->height) + " data window");
  if (w->width * w->height > kMostPixels)
    throw ImageError(path + ": the OpenEXR data window of " + std::to_string(w->width) + "x" +
                     std::to_string(w->height) + " pixels is larger than clrt reads");
  const std::int64_t chunks =
      w->tile_width > 0 && w->tile_height > 0
          ? ((w->width + w->tile_width - 1) / w->tile_width) *
                ((w->height + w->tile_height - 1) / w->tile_height)
          : (w->height + kMostLinesPerChunk - 1) / kMostLinesPerChunk;
  if (chunks * 8 > static_cast<std::int64_t>(bytes.size()))
    throw ImageError(path + ": not a readable OpenEXR file: its data window needs " +
                     std::to_string(chunks) + " chunks, more than its " +
                     std::to_string(bytes.size()) + " bytes can hold");
}

}  // namespace clrt::image_detail
