#include "gif_writer.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <memory>

#include "image/byte_sink.hpp"
#include "image/output_target.hpp"

namespace clrt::img {
namespace {

// The 8x8 Bayer matrix: thresholds 0..63, each step of the pattern as far as possible from the
// ones before it.
constexpr std::uint8_t kBayer8[8][8] = {
    {0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26},
    {12, 44, 4, 36, 14, 46, 6, 38}, {60, 28, 52, 20, 62, 30, 54, 22},
    {3, 35, 11, 43, 1, 33, 9, 41},  {51, 19, 59, 27, 49, 17, 57, 25},
    {15, 47, 7, 39, 13, 45, 5, 37}, {63, 31, 55, 23, 61, 29, 53, 21}};

// The palette level below `value` or, by the share of the way to the next level against the
// threshold, the one above: a value on the palette stays exact, one between two levels mixes
// them in proportion. In integers, so the bytes never depend on floating-point rounding.
int dithered_level(int channel, int value, int threshold) {
  const int steps = kGifLevels[channel] - 1;
  int level = value * steps / 255;
  while (level < steps && gif_level_value(channel, level + 1) <= value) ++level;
  if (level == steps) return level;
  const int low = gif_level_value(channel, level), high = gif_level_value(channel, level + 1);
  return (value - low) * 128 > (2 * threshold + 1) * (high - low) ? level + 1 : level;
}

struct GifCloser {
  void operator()(GifFileType* gif) const { EGifCloseFile(gif, nullptr); }
};

// Where giflib's pieces of the file go: the sink, with a failure to write kept to be rethrown
// once giflib has returned (an exception must not unwind through its C frames).
struct GifOutput {
  image_detail::ByteSink* sink;
  std::exception_ptr failure;
};

int put_bytes(GifFileType* gif, const GifByteType* data, int size) {
  auto* out = static_cast<GifOutput*>(gif->UserData);
  if (out->failure) return 0;
  try {
    out->sink->write(data, static_cast<std::size_t>(size));
  } catch (...) {
    out->failure = std::current_exception();
    return 0;
  }
  return size;
}

void check(int status, GifFileType* gif, const char* step) {
  if (status == GIF_ERROR)
    throw ImageError(std::string("GIF encoder: ") + step + ": " + GifErrorString(gif->Error));
}

ColorMapObject* fixed_palette() {
  ColorMapObject* map = GifMakeMapObject(256, nullptr);
  if (!map) throw ImageError("GIF encoder: out of memory for the palette");
  for (int i = 0; i < 256; ++i) {
    const int r = i / (kGifLevels[1] * kGifLevels[2]), g = i / kGifLevels[2] % kGifLevels[1],
              b = i % kGifLevels[2];
    const bool used = r < kGifLevels[0];
    map->Colors[i] = {used ? gif_level_value(0, r) : std::uint8_t{0},
                      used ? gif_level_value(1, g) : std::uint8_t{0},
                      used ? gif_level_value(2, b) : std::uint8_t{0}};
  }
  return map;
}

// NETSCAPE2.0 with a loop count of 0: the animation repeats for ever.
void put_loop_forever(GifFileType* gif) {
  static const char kApp[] = "NETSCAPE2.0";
  static const GifByteType kLoop[] = {1, 0, 0};
  check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), gif, "loop");
  check(EGifPutExtensionBlock(gif, 11, kApp), gif, "loop");
  check(EGifPutExtensionBlock(gif, sizeof kLoop, kLoop), gif, "loop");
  check(EGifPutExtensionTrailer(gif), gif, "loop");
}

void put_frame(GifFileType* gif, const Rgba8Image& image, const std::vector<std::uint8_t>& rgba,
               int delay_cs) {
  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_DO_NOT;
  control.DelayTime = delay_cs;
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const auto length = EGifGCBToExtension(&control, extension);
  check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension), gif,
        "frame delay");
  check(EGifPutImageDesc(gif, 0, 0, image.width, image.height, false, nullptr), gif, "frame");
  std::vector<GifPixelType> row(static_cast<std::size_t>(image.width));
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x)
      row[x] = gif_palette_index(&rgba[4 * (std::size_t(y) * image.width + x)], x, y);
    check(EGifPutLine(gif, row.data(), image.width), gif, "pixels");
  }
}

// The whole file, piece by piece, to `out`; ImageError when giflib fails.
void encode_frames(const Rgba8Image& image, int delay_cs, GifOutput& out) {
  int error = 0;
  std::unique_ptr<GifFileType, GifCloser> gif(EGifOpen(&out, put_bytes, &error));
  if (!gif) throw ImageError(std::string("GIF encoder: ") + GifErrorString(error));
  EGifSetGifVersion(gif.get(), true);
  ColorMapObject* palette = fixed_palette();
  const int status = EGifPutScreenDesc(gif.get(), image.width, image.height, 8, 0, palette);
  GifFreeMapObject(palette);
  check(status, gif.get(), "screen");
  if (image.frames.size() > 1) put_loop_forever(gif.get());
  for (const auto& frame : image.frames) put_frame(gif.get(), image, frame, delay_cs);
  GifFileType* done = gif.release();
  if (EGifCloseFile(done, &error) == GIF_ERROR)
    throw ImageError(std::string("GIF encoder: ") + GifErrorString(error));
}

}  // namespace

std::uint8_t gif_level_value(int channel, int level) {
  const int steps = kGifLevels[channel] - 1;
  return static_cast<std::uint8_t>((level * 255 + steps / 2) / steps);
}

std::uint8_t gif_palette_index(const std::uint8_t rgb[3], int x, int y) {
  const int threshold = kBayer8[y & 7][x & 7];
  const int r = dithered_level(0, rgb[0], threshold), g = dithered_level(1, rgb[1], threshold),
            b = dithered_level(2, rgb[2], threshold);
  return static_cast<std::uint8_t>((r * kGifLevels[1] + g) * kGifLevels[2] + b);
}

void encode_gif(const Rgba8Image& image, int delay_cs, image_detail::ByteSink& sink) {
  if (image.width > 65535 || image.height > 65535)
    throw ImageError("GIF cannot hold an image of " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " (at most 65535 a side)");
  GifOutput out{&sink, nullptr};
  try {
    encode_frames(image, delay_cs, out);
  } catch (const ImageError&) {
    if (out.failure) std::rethrow_exception(out.failure);
    throw;
  }
  if (out.failure) std::rethrow_exception(out.failure);
}

void write_gif(const std::string& path, const Rgba8Image& image, int delay_cs) {
  // The sink every image gets: a link stays a link, a FIFO or device is written through.
  const std::unique_ptr<image_detail::ByteSink> sink = image_detail::open_output_sink(path);
  encode_gif(image, delay_cs, *sink);
  sink->finish();
}

bool is_gif_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string end = path.substr(path.size() - 4);
  std::transform(end.begin(), end.end(), end.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return end == ".gif";
}

}  // namespace clrt::img
