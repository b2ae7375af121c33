// OpenEXR: half and float round trips, the data window as placement, and the files clrt reads
// but never writes (grey, overscan), made here with OpenEXR itself.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "test_files.hpp"

using clrt::FloatImage;
using clrt::ImageError;
using clrt::Placement;
using Catch::Matchers::Contains;
using namespace clrt::test;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), 4 * a.size()) == 0;
}

// What info says of the samples of the EXR at `path`.
void check_samples(const std::string& path, const std::string& samples, bool float32) {
  const clrt::ImageInfo info = clrt::read_image_info(path);
  CHECK(info.samples == samples);
  CHECK(info.float32 == float32);
}

// A one-channel file named `channel` over `data` (inclusive corners) inside `display`.
void write_one_channel(const std::string& path, const char* channel, Imath::Box2i display,
                       Imath::Box2i data, const std::vector<float>& values) {
  Imf::Header header(display, data);
  header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer frame_buffer;
  frame_buffer.insert(channel, Imf::Slice::Make(Imf::FLOAT, values.data(), data));
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame_buffer);
  file.writePixels(data.max.y - data.min.y + 1);
}

}  // namespace

TEST_CASE("EXR is half by default: each float rounds once, to the nearest half, ties to even",
          "[image][exr]") {
  ScratchDir dir;
  const std::string path = dir.file("a.exr");
  // Worked out by hand with 10 fraction bits: 0.1 -> 1.599609375 * 2^-4; 1/3 -> 1365 / 4096;
  // 1000.7 -> 512 * (1 + 977 / 1024); 70000 is past the largest half (65504) and becomes inf;
  // 1e-8 is below half the smallest subnormal (2^-25); 1 + 2^-11 and 1 + 3 * 2^-11 are ties
  // that go to the even neighbour, 1 and 1 + 2^-9.
  clrt::write_image(path, FloatImage{3, 1,
                                     {0.1f, 1.0f / 3.0f, 1000.7f, 70000.0f, -2.0f, 0.0f, 1e-8f,
                                      1.00048828125f, 1.00146484375f}});
  const FloatImage back = clrt::read_exr(path);
  CHECK(back.width == 3);
  CHECK(back.height == 1);
  CHECK_FALSE(back.placement);
  CHECK(same_bits(back.rgb, {0.0999755859375f, 0.333251953125f, 1000.5f, kInfinity, -2.0f, 0.0f,
                             0.0f, 1.0f, 1.001953125f}));
  check_samples(path, "16-bit float (half)", false);
}

TEST_CASE("a half EXR says once how many finite samples it stored as infinity", "[image][exr]") {
  // 65519 rounds down to 65504, 65520 up to infinity; infinities and NaNs were never finite.
  ScratchDir dir;
  const std::string path = dir.file("bright.exr");
  const FloatImage image{2, 2, {65504.0f, 65519.0f, 65520.0f, -1e6f, kInfinity, std::nanf(""), 3e38f,
                                1.0f, -65520.0f, 0.5f, 2.0f, 4.0f}};
  std::vector<std::string> warnings;
  clrt::WriteOptions options;
  options.warn = [&](const std::string& message) { warnings.push_back(message); };
  clrt::write_image(path, image, options);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings.front() == path + ": 4 of the 12 samples are beyond 65504, the largest half "
                                   "float, and are stored as infinity (--exr-pixel float keeps them)");
  const FloatImage back = clrt::read_exr(path);
  CHECK(back.rgb[1] == 65504.0f);
  CHECK(back.rgb[2] == kInfinity);
  CHECK(back.rgb[3] == -kInfinity);

  warnings.clear();
  clrt::write_image(path, FloatImage{1, 1, {65519.0f, -65519.0f, kInfinity}}, options);
  clrt::write_image(path, image, [&] {
    clrt::WriteOptions float_options{clrt::ExrPixel::Float};
    float_options.warn = options.warn;
    return float_options;
  }());
  CHECK(warnings.empty());
}

TEST_CASE("EXR with --exr-pixel float keeps every float's bits", "[image][exr]") {
  ScratchDir dir;
  const std::string path = dir.file("a.exr");
  const FloatImage image{2, 2, {0.1f, 1e30f, -3e-40f, 65504.5f, 1.0f / 3.0f, -0.0f, 7.0f, 8.0f,
                                9.0f, 1e-7f, 2e7f, -1.0f}};
  clrt::write_image(path, image, {clrt::ExrPixel::Float});
  CHECK(same_bits(clrt::read_exr(path).rgb, image.rgb));
  check_samples(path, "32-bit float", true);
}

TEST_CASE("every 8-bit value survives a half EXR and quantises back to itself", "[image][exr]") {
  ScratchDir dir;
  const std::string path = dir.file("ramp.exr");
  Bytes rgba;
  for (int v = 0; v < 256; ++v) rgba.insert(rgba.end(), {Bytes::value_type(v), 0, 255, 255});
  const clrt::Rgba8Image ramp{256, 1, {rgba}};
  clrt::write_image(path, ramp);
  CHECK(clrt::read_image(path).frames == ramp.frames);
}

TEST_CASE("EXR stores a placement as the data window inside the display window",
          "[image][exr][placement]") {
  ScratchDir dir;
  const std::string path = dir.file("tile.exr");
  const FloatImage tile(2, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18},
                        Placement{5, 7, 20, 10});
  clrt::write_image(path, tile);
  const FloatImage back = clrt::read_exr(path);
  CHECK(back.placement == Placement{5, 7, 20, 10});
  CHECK(back.rgb == tile.rgb);
  CHECK(clrt::info_text(clrt::read_image_info(path)) ==
        "format: EXR\nwidth: 2\nheight: 3\nframes: 1\nchannels: B, G, R\n"
        "samples: 16-bit float (half)\nplacement: 5,7 2x3 of 20x10\n"
        "data window: (5, 7) - (6, 9)\ndisplay window: (0, 0) - (19, 9)\n"
        "compression: ZIP\nstorage: scanlines\n");
  // The placement is the data window's offset from the display window, wherever that starts.
  write_one_channel(path, "Y", Imath::Box2i({-4, -2}, {5, 7}), Imath::Box2i({-3, 0}, {-3, 0}),
                    {0.5f});
  CHECK(clrt::read_exr(path).placement == Placement{1, 2, 10, 10});
}

TEST_CASE("EXR reader copies Y to R, G, B and ignores a data window outside the display window",
          "[image][exr]") {
  ScratchDir dir;
  const std::string path = dir.file("grey.exr");
  write_one_channel(path, "Y", Imath::Box2i({0, 0}, {1, 0}), Imath::Box2i({-1, 0}, {1, 0}),
                    {0.25f, 0.5f, 2.0f});
  const FloatImage grey = clrt::read_exr(path);
  CHECK(grey.width == 3);
  CHECK(grey.rgb == std::vector<float>{0.25f, 0.25f, 0.25f, 0.5f, 0.5f, 0.5f, 2, 2, 2});
  CHECK_FALSE(grey.placement);
  const clrt::ImageInfo info = clrt::read_image_info(path);
  CHECK(info.channels == "Y");
  CHECK(info.float32);

  write_one_channel(path, "Z", Imath::Box2i({0, 0}, {0, 0}), Imath::Box2i({0, 0}, {0, 0}), {1});
  CHECK_THROWS_WITH(clrt::read_exr(path), Contains(path) && Contains("no R, G, B or Y channel"));
}

TEST_CASE("EXR reader rejects what is not a whole OpenEXR file, naming it", "[image][exr]") {
  ScratchDir dir;
  const std::string path = dir.file("bad.exr");
  write_bytes(path, bytes_of("P6\n1 1\n255\nabc"));
  CHECK_THROWS_WITH(clrt::read_exr(path), Contains(path) && Contains("the file holds a PPM image"));
  write_bytes(path, bytes_of("no image at all"));
  CHECK_THROWS_WITH(clrt::read_exr(path), Contains(path) && Contains("not a readable OpenEXR"));
  clrt::write_image(path, FloatImage{4, 4, std::vector<float>(48, 0.5f)});
  const Bytes whole = read_bytes(path);
  write_bytes(path, Bytes(whole.begin(), whole.begin() + static_cast<long>(whole.size() / 2)));
  CHECK_THROWS_WITH(clrt::read_exr(path), Contains(path));
  CHECK_THROWS_AS(clrt::read_exr(dir.file("missing.exr")), ImageError);
}

TEST_CASE("an EXR header that declares more than the file holds is refused before OpenEXR reads it",
          "[image][exr]") {
  // fuzz_image_exr's 300-byte file: an attribute whose size field reads 1886220131 made
  // OpenEXR allocate 1.9 GB before finding the file too short.
  const std::string forged = std::string(CLRT_SOURCE_DIR) +
                             "/tests/fuzz/regressions/fuzz_image_exr/attribute-size-1886220131.exr";
  CHECK_THROWS_WITH(clrt::read_exr(forged), Contains("declares 1886220131 bytes"));

  // A small, valid file whose data window is made 65536 lines tall (its offset table alone
  // would need 256 chunks), then 65537 and 200 million (beyond the side clrt reads).
  ScratchDir dir;
  const std::string path = dir.file("tall.exr");
  clrt::write_image(path, FloatImage(4, 3, std::vector<float>(36, 0.5f)));
  Bytes bytes = read_bytes(path);
  const std::string text(bytes.begin(), bytes.end());
  const std::size_t window = text.find("dataWindow");
  REQUIRE(window != std::string::npos);
  const std::size_t y_max = window + std::strlen("dataWindow") + 1 + std::strlen("box2i") + 1 + 4 + 12;
  for (const auto& [lines, message] : {std::pair<std::int32_t, const char*>{65535, "needs 256 chunks"},
                                       {65536, "larger than clrt reads"},
                                       {200000000, "larger than clrt reads"}}) {
    std::memcpy(&bytes[y_max], &lines, 4);
    write_bytes(path, bytes);
    CHECK_THROWS_WITH(clrt::read_exr(path), Contains(message));
  }
}

TEST_CASE("an EXR header OpenEXR would read past its sizes, or without what it requires, is refused",
          "[image][exr]") {
  // fuzz_image_exr's files: a channel list that does not end where its size says, beside a
  // channel whose y sampling reads 1919247474 (OpenEXR asked for 1.8 GB); a channel of pixel
  // type 16777215 in a header cut short (1.9 GB).
  const std::string found = std::string(CLRT_SOURCE_DIR) + "/tests/fuzz/regressions/fuzz_image_exr/";
  CHECK_THROWS_WITH(clrt::read_exr(found + "channel-sampling-1919247474.exr"),
                    Contains("'channels' does not end where its size says"));
  CHECK_THROWS_WITH(clrt::read_exr(found + "channel-type-16777215.exr"),
                    Contains("channel 'G' has no pixel type OpenEXR knows"));

  // A valid file whose first channel's y sampling is made 7, then 0; then one whose
  // compression attribute is renamed.
  ScratchDir dir;
  const std::string path = dir.file("sampled.exr");
  clrt::write_image(path, FloatImage(4, 3, std::vector<float>(36, 0.5f)));
  const Bytes valid = read_bytes(path);
  Bytes bytes = valid;
  const std::string text(bytes.begin(), bytes.end());
  const std::size_t list = text.find("chlist");
  REQUIRE(list != std::string::npos);
  // chlist\0, the size, then the first channel: its name\0, type, pLinear and reserved, x, y.
  const std::size_t first = list + std::strlen("chlist") + 1 + 4;
  const std::size_t y_sampling = text.find('\0', first) + 1 + 4 + 4 + 4;
  for (const auto& [sampling, message] :
       {std::pair<std::int32_t, const char*>{7, "sampling does not fit its 4x3 data window"},
        {0, "has a sampling below 1"}}) {
    INFO(sampling);
    std::memcpy(&bytes[y_sampling], &sampling, 4);
    write_bytes(path, bytes);
    CHECK_THROWS_WITH(clrt::read_exr(path), Contains(message));
  }
  bytes = valid;
  const std::size_t compression = text.find("compression");
  REQUIRE(compression != std::string::npos);
  bytes[compression + std::strlen("compression") - 1] = 'x';
  write_bytes(path, bytes);
  CHECK_THROWS_WITH(clrt::read_exr(path), Contains("its header has no 'compression' attribute"));
}

TEST_CASE("an EXR line longer than clrt's longest side is refused before OpenEXR decodes it",
          "[image][exr]") {
  // fuzz_image_exr's 389-byte file: a ZIP data window 5963777 pixels wide, whose 16-line
  // chunk made OpenEXR's decompressor ask for 1.1 GB.
  const std::string wide = std::string(CLRT_SOURCE_DIR) +
                           "/tests/fuzz/regressions/fuzz_image_exr/line-5963777-wide.exr";
  CHECK_THROWS_WITH(clrt::read_exr(wide), Contains("5963777x2 pixels is larger than clrt reads"));
}
