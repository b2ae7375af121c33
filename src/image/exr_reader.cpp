// OpenEXR: the R, G and B channels of the data window (a missing one reads as 0), or Y copied to
// all three for a grey file; other channels (alpha, layers) are listed by info but not read.
// Half and 32-bit float channels convert to float exactly. A data window that lies inside the
// display window and differs from it is the image's placement in the full frame.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <algorithm>
#include <climits>
#include <new>

#include "image/exr_header_check.hpp"
#include "image/checked_size.hpp"
#include "image/decoders.hpp"
#include "image/exr_streams.hpp"

namespace clrt {
namespace {

std::string type_name(Imf::PixelType type) {
  switch (type) {
    case Imf::HALF:
      return "16-bit float (half)";
    case Imf::FLOAT:
      return "32-bit float";
    default:
      return "32-bit unsigned integer";
  }
}

std::string compression_name(Imf::Compression compression) {
  constexpr const char* kNames[] = {"none", "RLE",  "ZIPS", "ZIP",  "PIZ",
                                    "PXR24", "B44", "B44A", "DWAA", "DWAB"};
  const auto index = static_cast<std::size_t>(compression);
  return index < std::size(kNames) ? kNames[index] : "unknown";
}

std::string window_text(const Imath::Box2i& window) {
  return "(" + std::to_string(window.min.x) + ", " + std::to_string(window.min.y) + ") - (" +
         std::to_string(window.max.x) + ", " + std::to_string(window.max.y) + ")";
}

// An open file's header read as clrt reads it: which channels, the size, the placement.
struct ExrLayout {
  std::vector<std::string> read;  // "R", "G", "B" (those present), or "Y"
  int width = 0, height = 0;
  std::optional<Placement> placement;
};

ExrLayout layout_of(const Imf::Header& header, const std::string& path) {
  ExrLayout layout;
  const Imf::ChannelList& channels = header.channels();
  for (const char* name : {"R", "G", "B"})
    if (channels.findChannel(name)) layout.read.emplace_back(name);
  if (layout.read.empty() && channels.findChannel("Y")) layout.read.emplace_back("Y");
  if (layout.read.empty())
    throw ImageError(path + ": the OpenEXR file has no R, G, B or Y channel");
  const Imath::Box2i& data = header.dataWindow();
  const Imath::Box2i& display = header.displayWindow();
  const std::int64_t width = std::int64_t{data.max.x} - data.min.x + 1;
  const std::int64_t height = std::int64_t{data.max.y} - data.min.y + 1;
  if (width > INT_MAX / 3 || height > INT_MAX)
    throw ImageError(path + ": the OpenEXR data window " + window_text(data) + " is too large");
  layout.width = static_cast<int>(width);
  layout.height = static_cast<int>(height);
  if (display.intersects(data.min) && display.intersects(data.max) && data != display)
    layout.placement =
        Placement{data.min.x - display.min.x, data.min.y - display.min.y,
                  display.max.x - display.min.x + 1, display.max.y - display.min.y + 1};
  return layout;
}

// OpenEXR reports errors as exceptions derived from std::exception.
template <typename Read>
auto read_exr_file(const ImageBytes& encoded, const Read& read) {
  const std::string& path = encoded.name;
  image_detail::check_exr_window(encoded.bytes, path);
  try {
    image_detail::MemoryIStream stream(encoded.bytes, path.c_str());
    Imf::InputFile file(stream);
    return read(file, layout_of(file.header(), path));
  } catch (const ImageError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw ImageError(path + ": not enough memory to read this OpenEXR file");
  } catch (const std::exception& error) {
    throw ImageError(path + ": not a readable OpenEXR file: " + error.what());
  }
}

}  // namespace

FloatImage image_detail::exr_pixels(const ImageBytes& encoded) {
  return read_exr_file(encoded, [](Imf::InputFile& file, const ExrLayout& layout) {
    const Imath::Box2i& window = file.header().dataWindow();
    std::vector<float> rgb(3 * static_cast<std::size_t>(layout.width) *
                           static_cast<std::size_t>(layout.height));
    const std::size_t x_stride = 3 * sizeof(float);
    const std::size_t y_stride = x_stride * static_cast<std::size_t>(layout.width);
    Imf::FrameBuffer frame_buffer;
    const bool grey = layout.read.front() == "Y";
    for (std::size_t c = 0; c < (grey ? 1 : 3); ++c)
      frame_buffer.insert(grey ? "Y" : std::string(1, "RGB"[c]),
                          Imf::Slice::Make(Imf::FLOAT, rgb.data() + c, window, x_stride, y_stride));
    file.setFrameBuffer(frame_buffer);
    file.readPixels(window.min.y, window.max.y);
    if (grey)
      for (std::size_t i = 0; i < rgb.size(); i += 3) rgb[i + 1] = rgb[i + 2] = rgb[i];
    return FloatImage(layout.width, layout.height, std::move(rgb), layout.placement);
  });
}

ImageInfo image_detail::exr_info(const ImageBytes& encoded) {
  return read_exr_file(encoded, [](Imf::InputFile& file, const ExrLayout& layout) {
    const Imf::Header& header = file.header();
    std::string names;
    std::vector<Imf::PixelType> read_types;
    for (auto channel = header.channels().begin(); channel != header.channels().end();
         ++channel) {
      names += (names.empty() ? "" : ", ") + std::string(channel.name());
      if (std::find(layout.read.begin(), layout.read.end(), channel.name()) != layout.read.end())
        read_types.push_back(channel.channel().type);
    }
    const bool uniform = std::all_of(read_types.begin(), read_types.end(),
                                     [&](Imf::PixelType t) { return t == read_types.front(); });
    ImageInfo info = image_detail::basic_info(ImageFormat::Exr, layout.width, layout.height, names,
                                              uniform ? type_name(read_types.front()) : "mixed");
    info.float32 = std::any_of(read_types.begin(), read_types.end(),
                               [](Imf::PixelType t) { return t != Imf::HALF; });
    info.placement = layout.placement;
    info.details = {{"data window", window_text(header.dataWindow())},
                    {"display window", window_text(header.displayWindow())},
                    {"compression", compression_name(header.compression())},
                    {"storage", header.hasTileDescription() ? "tiles" : "scanlines"}};
    return info;
  });
}

}  // namespace clrt
