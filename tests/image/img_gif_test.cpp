// clrt-img convert to GIF, read back with giflib's own decoder: frames, size, delays, the loop,
// and the colours through the fixed palette and its dithering.
#include <gif_lib.h>

#include <catch2/catch.hpp>
#include <memory>
#include <string>

#include "image/image.hpp"
#include "run_tool.hpp"

using clrt::Rgba8Image;
using namespace clrt::test;

namespace {

struct GifCloser {
  void operator()(GifFileType* gif) const { DGifCloseFile(gif, nullptr); }
};
using Gif = std::unique_ptr<GifFileType, GifCloser>;

Gif read_gif(const std::string& path) {
  int error = 0;
  Gif gif(DGifOpenFileName(path.c_str(), &error));
  REQUIRE(gif);
  REQUIRE(DGifSlurp(gif.get()) == GIF_OK);
  return gif;
}

// Every pixel of frame `frame` as RGB through the global palette.
std::vector<GifColorType> colours(const GifFileType& gif, int frame) {
  const SavedImage& image = gif.SavedImages[frame];
  std::vector<GifColorType> out;
  const int count = image.ImageDesc.Width * image.ImageDesc.Height;
  for (int i = 0; i < count; ++i) out.push_back(gif.SColorMap->Colors[image.RasterBits[i]]);
  return out;
}

int delay_cs(GifFileType* gif, int frame) {
  GraphicsControlBlock control{};
  REQUIRE(DGifSavedExtensionToGCB(gif, frame, &control) == GIF_OK);
  return control.DelayTime;
}

bool loops_forever(const GifFileType& gif) {
  const SavedImage& first = gif.SavedImages[0];
  for (int i = 0; i + 1 < first.ExtensionBlockCount; ++i) {
    const ExtensionBlock& block = first.ExtensionBlocks[i];
    if (block.Function == APPLICATION_EXT_FUNC_CODE && block.ByteCount == 11 &&
        std::string(reinterpret_cast<const char*>(block.Bytes), 11) == "NETSCAPE2.0") {
      const ExtensionBlock& loop = first.ExtensionBlocks[i + 1];
      return loop.ByteCount == 3 && loop.Bytes[0] == 1 && loop.Bytes[1] == 0 && loop.Bytes[2] == 0;
    }
  }
  return false;
}

// A width x height frame of one colour.
std::vector<std::uint8_t> flat(int width, int height, std::uint8_t r, std::uint8_t g,
                               std::uint8_t b) {
  std::vector<std::uint8_t> frame(4 * static_cast<std::size_t>(width * height), 255);
  for (std::size_t i = 0; i < frame.size(); i += 4) {
    frame[i] = r;
    frame[i + 1] = g;
    frame[i + 2] = b;
  }
  return frame;
}

}  // namespace

TEST_CASE("convert to GIF: every frame of an FSF, its size, the delay of --fps, looping",
          "[img][gif]") {
  ScratchDir dir;
  const std::string fsf = dir.file("turn.fsf"), gif_path = dir.file("turn.gif");
  const Rgba8Image animation{16, 8, {flat(16, 8, 0, 0, 0), flat(16, 8, 255, 255, 255),
                                     flat(16, 8, 255, 0, 0), flat(16, 8, 0, 255, 255)}};
  clrt::write_image(fsf, animation);
  const ToolResult result = run_img(dir, "convert " + quoted(fsf) + " " + quoted(gif_path) +
                                             " --fps 10");
  INFO(result.err);
  REQUIRE(result.status == 0);
  Gif gif = read_gif(gif_path);
  CHECK(gif->SWidth == 16);
  CHECK(gif->SHeight == 8);
  REQUIRE(gif->ImageCount == 4);
  CHECK(loops_forever(*gif));
  const GifColorType expected[4] = {{0, 0, 0}, {255, 255, 255}, {255, 0, 0}, {0, 255, 255}};
  for (int frame = 0; frame < 4; ++frame) {
    CHECK(delay_cs(gif.get(), frame) == 10);
    for (const GifColorType& c : colours(*gif, frame)) {
      CHECK(c.Red == expected[frame].Red);
      CHECK(c.Green == expected[frame].Green);
      CHECK(c.Blue == expected[frame].Blue);
    }
  }
}

TEST_CASE("info describes the GIFs convert writes: size, frames, delay, looping", "[img][gif]") {
  ScratchDir dir;
  const std::string fsf = dir.file("turn.fsf"), gif_path = dir.file("turn.gif");
  clrt::write_image(fsf, Rgba8Image{12, 5, {flat(12, 5, 0, 0, 0), flat(12, 5, 255, 0, 0),
                                            flat(12, 5, 0, 0, 255)}});
  REQUIRE(run_img(dir, "convert " + quoted(fsf) + " " + quoted(gif_path) + " --fps 4").status == 0);
  const ToolResult info = run_img(dir, "info " + quoted(gif_path));
  INFO(info.err);
  CHECK(info.status == 0);
  CHECK(info.out_text() == "file: " + gif_path +
                        "\nformat: GIF\nwidth: 12\nheight: 5\nframes: 3\nchannels: palette\n"
                        "samples: 8-bit\nplacement: none (GIF cannot record one)\n"
                        "frame delay: 0.25 s\nloops: yes\n");
  // Not a GIF inside: an error naming the file, exit 1 as for any unreadable image.
  const std::string fake = dir.write("fake.gif", "GIF? no\n");
  const ToolResult bad = run_img(dir, "info " + quoted(fake));
  CHECK(bad.status != 0);
  CHECK_THAT(bad.err, Catch::Contains(fake + ": not a readable GIF"));
}

TEST_CASE("convert to GIF: a colour between the palette's levels is dithered to its mean",
          "[img][gif]") {
  ScratchDir dir;
  const std::string png = dir.file("grey.png"), gif_path = dir.file("grey.gif");
  clrt::write_image(png, Rgba8Image{16, 16, {flat(16, 16, 100, 150, 30)}});
  REQUIRE(run_img(dir, "convert " + quoted(png) + " " + quoted(gif_path)).status == 0);
  Gif gif = read_gif(gif_path);
  REQUIRE(gif->ImageCount == 1);
  CHECK(delay_cs(gif.get(), 0) == 4);  // 25 frames per second
  double sum[3] = {0, 0, 0};
  const std::vector<GifColorType> pixels = colours(*gif, 0);
  for (const GifColorType& c : pixels) {
    sum[0] += c.Red;
    sum[1] += c.Green;
    sum[2] += c.Blue;
  }
  const double n = static_cast<double>(pixels.size());
  // An 8x8 matrix resolves the step between two levels into 64ths: within 1 of the colour.
  CHECK(sum[0] / n == Approx(100).margin(1));
  CHECK(sum[1] / n == Approx(150).margin(1));
  CHECK(sum[2] / n == Approx(30).margin(1));
}

TEST_CASE("convert to GIF: a float image is quantised as clrt quantises, --frame picks one",
          "[img][gif]") {
  ScratchDir dir;
  const std::string pfm = dir.file("hdr.pfm"), gif_path = dir.file("hdr.gif");
  clrt::write_image(pfm, clrt::FloatImage{2, 1, {3.0f, -1.0f, 1.0f, 0.0f, 0.0f, 0.0f}});
  REQUIRE(run_img(dir, "convert " + quoted(pfm) + " " + quoted(gif_path)).status == 0);
  Gif gif = read_gif(gif_path);
  const std::vector<GifColorType> pixels = colours(*gif, 0);
  REQUIRE(pixels.size() == 2);
  CHECK((pixels[0].Red == 255 && pixels[0].Green == 0 && pixels[0].Blue == 255));
  CHECK((pixels[1].Red == 0 && pixels[1].Green == 0 && pixels[1].Blue == 0));

  const std::string fsf = dir.file("two.fsf"), second = dir.file("second.gif");
  clrt::write_image(fsf, Rgba8Image{2, 2, {flat(2, 2, 0, 0, 0), flat(2, 2, 255, 255, 255)}});
  REQUIRE(run_img(dir, "convert " + quoted(fsf) + " " + quoted(second) + " --frame 2").status == 0);
  Gif one = read_gif(second);
  REQUIRE(one->ImageCount == 1);
  CHECK(colours(*one, 0)[0].Red == 255);
}
