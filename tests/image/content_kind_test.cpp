// A file is told by its content when its name says another format, and the decoders read bytes
// held in memory, one frame of an animation when asked.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "image/content_kind.hpp"
#include "image/image.hpp"
#include "image/image_info.hpp"
#include "test_files.hpp"

using namespace clrt;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

// The first bytes of real files of each kind, as their specifications give them.
const std::vector<std::pair<std::string, Bytes>> kHeads = {
    {"PNG", {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13}},
    {"JPEG", {0xff, 0xd8, 0xff, 0xe0, 0, 0x10, 'J', 'F', 'I', 'F', 0}},
    {"GIF", bytes_of("GIF89a")},
    {"TIFF", {'I', 'I', 42, 0, 8, 0, 0, 0}},
    {"TIFF", {'M', 'M', 0, 42, 0, 0, 0, 8}},
    {"WebP", {'R', 'I', 'F', 'F', 0x24, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', ' '}},
    {"Radiance HDR", bytes_of("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n")},
    {"BMP", {'B', 'M', 0x46, 0, 0, 0, 0, 0, 0, 0, 0x36, 0}},
    {"OpenEXR", {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0}},
    {"FSF", {0x3f, 0x02, 0, 0, 1, 0, 0, 0}},
    {"FSF", {0, 0, 0x02, 0x3f, 0, 0, 0, 1}},
    {"PPM", bytes_of("P6\n1 1\n255\n")},
    {"PFM", bytes_of("Pf 1 1 -1\n")},
    {"PGM", bytes_of("P5\n1 1\n255\n")},
};

// An FSF of `frames` 1x1 frames, frame i of value i + 1.
Bytes fsf_frames(std::uint8_t frames) {
  Bytes file = {0x3f, 0x02, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, frames, 0, 0, 0};
  for (std::uint8_t i = 0; i < frames; ++i) file.insert(file.end(), 4, static_cast<std::uint8_t>(i + 1));
  return file;
}

}  // namespace

TEST_CASE("each known signature is told by its first bytes, and others are not", "[image][content]") {
  for (const auto& [kind, head] : kHeads) {
    INFO(kind);
    CHECK(image_detail::content_kind(ByteSpan(head)) == kind);
  }
  // Text that starts like a signature is not one: "P6" needs whitespace after it, BMP zeros.
  for (const std::string text : {"P6x", "BMW 3 series", "plain text", "", "#?"})
    CHECK(image_detail::content_kind(ByteSpan(std::string_view(text))).empty());
}

TEST_CASE("an image named as another format says which format it holds", "[image][content]") {
  ScratchDir dir;
  const Bytes jpeg = kHeads[1].second;
  write_bytes(dir.file("photo.png"), jpeg);
  const std::string holds_jpeg = "photo.png: the name says PNG, but the file holds a JPEG image; clrt reads "
                                 "FSF, PNG, PPM, PFM and OpenEXR images, so convert it to one of those";
  CHECK_THAT(error_of([&] { read_png(dir.file("photo.png")); }), Contains(holds_jpeg));
  CHECK_THAT(error_of([&] { read_image_info(dir.file("photo.png")); }), Contains(holds_jpeg));
  // A readable format under the wrong name is told how to read it.
  write_image(dir.file("real.png"), Rgba8Image(1, 1, {{1, 2, 3, 255}}));
  const Bytes png = read_bytes(dir.file("real.png"));
  for (const char* name : {"a.fsf", "a.exr", "a.ppm"}) {
    write_bytes(dir.file(name), png);
    INFO(name);
    CHECK_THAT(error_of([&] { read_any_image(dir.file(name)); }),
               Contains("but the file holds a PNG image; name it .png to read it as one"));
    CHECK_THAT(error_of([&] { read_image_info(dir.file(name)); }), Contains("holds a PNG image"));
  }
  write_bytes(dir.file("frames.png"), fsf_frames(2));
  CHECK_THAT(error_of([&] { read_png(dir.file("frames.png")); }),
             Contains("the name says PNG, but the file holds an FSF image; name it .fsf"));
  // Bytes of no known kind keep the format's own message.
  write_bytes(dir.file("junk.png"), bytes_of("not an image at all"));
  CHECK_THAT(error_of([&] { read_png(dir.file("junk.png")); }), Contains("not a readable PNG"));
}

TEST_CASE("images decode from bytes in memory, an animation's first frame alone when asked",
          "[image][content]") {
  const Bytes fsf = fsf_frames(3);
  const ImageBytes file{ByteSpan(fsf), "held/in/memory.fsf"};
  const Rgba8Image all = std::get<Rgba8Image>(decode_image(file, ImageFormat::Fsf));
  CHECK(all.frames == std::vector<Bytes>{{1, 1, 1, 1}, {2, 2, 2, 2}, {3, 3, 3, 3}});
  const Rgba8Image first = std::get<Rgba8Image>(decode_image(file, ImageFormat::Fsf, Frames::First));
  CHECK(first.frames == std::vector<Bytes>{{1, 1, 1, 1}});
  CHECK(decode_image_info(file, ImageFormat::Fsf).frames == 3);
  // The name is the messages' only: nothing is read from it.
  const Bytes cut(fsf.begin(), fsf.end() - 1);
  CHECK_THAT(error_of([&] { decode_image({ByteSpan(cut), "held/in/memory.fsf"}, ImageFormat::Fsf); }),
             Contains("held/in/memory.fsf: the FSF header describes 1x1, 3 frame(s)") && Contains("truncated"));
  ScratchDir dir;
  const FloatImage floats(2, 1, {0.5f, 1, 2, 3, 4, 5});
  write_image(dir.file("f.exr"), floats, WriteOptions(ExrPixel::Float));
  const Bytes exr = read_bytes(dir.file("f.exr"));
  CHECK(std::get<FloatImage>(decode_image({ByteSpan(exr), "f.exr"}, ImageFormat::Exr)).rgb == floats.rgb);
}
