// OpenEXR through its general interface, whose frame buffer must hold the file's own pixel type:
// 32-bit float channels are written straight from the image's floats; half channels from a strip
// of rows converted once each (Imath's half(float), round to nearest even), so the copy stays a
// few rows. ZIP compression (lossless, OpenEXR's default), scanlines from the top. A placement
// becomes the data window inside a display window of the full frame.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "image/encoders.hpp"
#include "image/exr_streams.hpp"

namespace clrt::image_detail {
namespace {

constexpr const char* kChannels[] = {"R", "G", "B"};
constexpr int kStripRows = 16;  // ZIP compresses blocks of 16 scanlines

Imath::Box2i window(int x, int y, int width, int height) {
  return Imath::Box2i(Imath::V2i(x, y), Imath::V2i(x + width - 1, y + height - 1));
}

// R, G, B slices over interleaved samples of `sample_bytes` each, `samples` being pixel `origin`.
Imf::FrameBuffer interleaved(Imf::PixelType type, const void* samples, std::size_t sample_bytes,
                             Imath::V2i origin, int width, int height) {
  Imf::FrameBuffer frame_buffer;
  const std::size_t x_stride = 3 * sample_bytes;
  for (std::size_t c = 0; c < 3; ++c)
    frame_buffer.insert(
        kChannels[c],
        Imf::Slice::Make(type, static_cast<const char*>(samples) + c * sample_bytes, origin,
                         width, height, x_stride, x_stride * static_cast<std::size_t>(width)));
  return frame_buffer;
}

// Returns how many finite samples became infinities: beyond 65504, the largest half (from
// 65520 up, as rounding to nearest makes it).
std::uint64_t write_half_strips(Imf::OutputFile& file, const FloatImage& image,
                                Imath::V2i origin) {
  const std::size_t row_samples = 3 * static_cast<std::size_t>(image.width);
  std::vector<Imath::half> strip(row_samples * kStripRows);
  std::uint64_t overflowed = 0;
  for (int y = 0; y < image.height; y += kStripRows) {
    const int rows = std::min(kStripRows, image.height - y);
    const float* in = image.rgb.data() + row_samples * static_cast<std::size_t>(y);
    for (std::size_t i = 0; i < row_samples * static_cast<std::size_t>(rows); ++i) {
      strip[i] = Imath::half(in[i]);
      overflowed += strip[i].isInfinity() && std::isfinite(in[i]);
    }
    file.setFrameBuffer(interleaved(Imf::HALF, strip.data(), sizeof(Imath::half),
                                    Imath::V2i(origin.x, origin.y + y), image.width, rows));
    file.writePixels(rows);
  }
  return overflowed;
}

std::string overflow_warning(std::uint64_t overflowed, std::uint64_t samples) {
  return std::to_string(overflowed) + " of the " + std::to_string(samples) +
         " samples are beyond 65504, the largest half float, and are stored as infinity "
         "(--exr-pixel float keeps them)";
}

}  // namespace

void encode_exr(const FloatImage& image, ExrPixel pixel, const Warn& warn, ByteSink& sink,
                const std::string& samples) {
  const Placement placement = image.placement.value_or(Placement{0, 0, image.width, image.height});
  const Imath::Box2i data_window = window(placement.x, placement.y, image.width, image.height);
  Imf::Header header(window(0, 0, placement.full_width, placement.full_height), data_window);
  const Imf::PixelType type = pixel == ExrPixel::Half ? Imf::HALF : Imf::FLOAT;
  for (const char* name : kChannels) header.channels().insert(name, Imf::Channel(type));
  if (!samples.empty()) header.insert(kSamplesKey, Imf::StringAttribute(samples));
  // OpenEXR stores a block raw when ZIP would not shrink it, so the file is at most the raw
  // samples, 16 bytes a block (its offset, row and size) and the header.
  const std::size_t raw = 3 * static_cast<std::size_t>(image.width) *
                          static_cast<std::size_t>(image.height) * (type == Imf::HALF ? 2 : 4);
  const std::size_t blocks = static_cast<std::size_t>(image.height / kStripRows + 1);
  MemoryOStream stream(raw + 16 * blocks + (std::size_t{1} << 16));
  std::uint64_t overflowed = 0;
  try {
    // The file's destructor writes the offset table; in memory that cannot fail.
    Imf::OutputFile file(stream, header);
    if (type == Imf::HALF) {
      overflowed = write_half_strips(file, image, data_window.min);
    } else {
      file.setFrameBuffer(interleaved(Imf::FLOAT, image.rgb.data(), sizeof(float),
                                      data_window.min, image.width, image.height));
      file.writePixels(image.height);
    }
  } catch (const std::exception& error) {
    throw ImageError(std::string("OpenEXR encoding failed: ") + error.what());
  }
  sink.write(stream.bytes().data(), stream.bytes().size());
  if (overflowed && warn) warn(overflow_warning(overflowed, image.rgb.size()));
}

}  // namespace clrt::image_detail
