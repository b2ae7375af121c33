#include "gif_info.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <sstream>

#include "image/image.hpp"

namespace clrt::img {
namespace {

struct GifReaderCloser {
  void operator()(GifFileType* gif) const { DGifCloseFile(gif, nullptr); }
};
using GifReader = std::unique_ptr<GifFileType, GifReaderCloser>;

[[noreturn]] void fail(const std::string& path, int error) {
  const char* why = GifErrorString(error);
  throw ImageError(path + ": not a readable GIF (" + (why ? why : "giflib error") + ")");
}

void check(int status, const GifReader& gif, const std::string& path) {
  if (status == GIF_ERROR) fail(path, gif->Error);
}

// Seconds from hundredths, as "0.04".
std::string seconds(int hundredths) {
  std::ostringstream out;
  out << hundredths / 100.0;
  return out.str();
}

}  // namespace

std::string gif_info_text(const std::string& path) {
  int error = 0;
  const GifReader gif(DGifOpenFileName(path.c_str(), &error));
  if (!gif) fail(path, error);
  std::uint64_t frames = 0;
  int shortest = -1, longest = -1;
  bool loops = false;
  GifRecordType record = UNDEFINED_RECORD_TYPE;
  do {
    check(DGifGetRecordType(gif.get(), &record), gif, path);
    if (record == IMAGE_DESC_RECORD_TYPE) {
      check(DGifGetImageDesc(gif.get()), gif, path);
      ++frames;
      // The frame's compressed blocks, skipped undecoded.
      int code_size = 0;
      GifByteType* block = nullptr;
      check(DGifGetCode(gif.get(), &code_size, &block), gif, path);
      while (block) check(DGifGetCodeNext(gif.get(), &block), gif, path);
    } else if (record == EXTENSION_RECORD_TYPE) {
      int code = 0;
      GifByteType* block = nullptr;
      check(DGifGetExtension(gif.get(), &code, &block), gif, path);
      if (code == GRAPHICS_EXT_FUNC_CODE && block) {
        GraphicsControlBlock control;
        if (DGifExtensionToGCB(block[0], block + 1, &control) == GIF_OK) {
          shortest = shortest < 0 ? control.DelayTime : std::min(shortest, control.DelayTime);
          longest = std::max(longest, control.DelayTime);
        }
      }
      if (code == APPLICATION_EXT_FUNC_CODE && block && block[0] >= 11 &&
          std::string(reinterpret_cast<const char*>(block + 1), 11) == "NETSCAPE2.0")
        loops = true;
      while (block) check(DGifGetExtensionNext(gif.get(), &block), gif, path);
    }
  } while (record != TERMINATE_RECORD_TYPE);
  std::string text = "format: GIF\nwidth: " + std::to_string(gif->SWidth) +
                     "\nheight: " + std::to_string(gif->SHeight) +
                     "\nframes: " + std::to_string(frames) +
                     "\nchannels: palette\nsamples: 8-bit\nplacement: none (GIF cannot record one)\n";
  if (longest >= 0)
    text += "frame delay: " +
            (shortest == longest ? seconds(longest) : seconds(shortest) + " to " + seconds(longest)) +
            " s\n";
  text += std::string("loops: ") + (loops ? "yes" : "no") + "\n";
  return text;
}

}  // namespace clrt::img
