#include <algorithm>
#include <tuple>
#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "png_chunks.hpp"
#include "test_files.hpp"

using clrt::ImageError;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

constexpr std::size_t kIhdrBitDepth = 24,
                      kIhdrColourType = 25;  // after signature, length, "IHDR", size
constexpr int kColourRgb = 2, kColourRgba = 6;

std::string fixture(const std::string& name) {
  return std::string(CLRT_SOURCE_DIR) + "/tests/image/data/" + name;
}

Rgba8Image read_fixture(const std::string& name) { return clrt::read_png(fixture(name)); }

}  // namespace

TEST_CASE("PNG round trips translucent RGBA exactly", "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("a.png");
  const Rgba8Image image{3, 2, {{0,  0,  0,  0,  255, 128, 1,  1,   9, 99, 199, 254,  //
                                 17, 34, 51, 68, 200, 100, 50, 255, 3, 2,  1,   127}}};
  clrt::write_image(path, image);
  const Bytes file = read_bytes(path);
  REQUIRE(file.size() > kIhdrColourType);
  CHECK(file[kIhdrBitDepth] == 8);
  CHECK(file[kIhdrColourType] == kColourRgba);
  const Rgba8Image back = clrt::read_png(path);
  CHECK(back.width == 3);
  CHECK(back.height == 2);
  CHECK(back.frames == image.frames);
}

TEST_CASE("PNG of an opaque image is 8-bit RGB and reads back with alpha 255", "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("rendered.PNG");  // the extension is matched case-insensitively
  clrt::write_image(path, clrt::FloatImage{2, 1, {0.5f, 1.5f, -1.0f, 0.2f, 0.0f, 1.0f}});
  const Bytes file = read_bytes(path);
  REQUIRE(file.size() > kIhdrColourType);
  CHECK(Bytes(file.begin(), file.begin() + 8) ==
        Bytes{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
  CHECK(file[kIhdrBitDepth] == 8);
  CHECK(file[kIhdrColourType] == kColourRgb);
  CHECK(clrt::read_png(path).frames == std::vector<Bytes>{{128, 255, 0, 255, 51, 0, 255, 255}});
}

TEST_CASE("PNG writer takes frame 0 of an animation", "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("anim.png");
  clrt::write_image(path, Rgba8Image{1, 1, {{1, 2, 3, 255}, {4, 5, 6, 255}}});
  CHECK(clrt::read_png(path).frames == std::vector<Bytes>{{1, 2, 3, 255}});
}

TEST_CASE("PNG reader converts other bit depths and colour types to 8-bit RGBA", "[image][png]") {
  SECTION("16-bit RGB: each sample becomes round(v * 255 / 65535)") {
    const Rgba8Image image = read_fixture("rgb16.png");
    CHECK(image.width == 2);
    CHECK(image.height == 1);
    // 0x1234 = 4660 -> 18.13; 0x8080 -> 128; 0x12c0 = 4800 -> 18.68; 0xfeff -> 254
    CHECK(image.frames == std::vector<Bytes>{{18, 128, 255, 255, 0, 19, 254, 255}});
  }
  SECTION("2-bit palette with tRNS transparency") {
    CHECK(read_fixture("palette2.png").frames ==
          std::vector<Bytes>{{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 10, 20, 30, 255}});
  }
  SECTION("1-bit grey") {
    const Rgba8Image image = read_fixture("gray1.png");
    CHECK(image.width == 8);
    CHECK(image.frames == std::vector<Bytes>{{255, 255, 255, 255, 0,   0,   0,   255,  //
                                              255, 255, 255, 255, 255, 255, 255, 255,  //
                                              0,   0,   0,   255, 0,   0,   0,   255,  //
                                              0,   0,   0,   255, 255, 255, 255, 255}});
  }
  SECTION("8-bit grey with alpha") {
    CHECK(read_fixture("gray_alpha8.png").frames ==
          std::vector<Bytes>{{100, 100, 100, 50, 200, 200, 200, 255}});
  }
}

TEST_CASE("PNG reader rejects a file that is not a PNG or is cut short, naming it",
          "[image][png]") {
  ScratchDir dir;
  const std::string path = dir.file("bad.png");
  write_bytes(path, bytes_of("P6\n1 1\n255\nabc"));
  CHECK_THROWS_WITH(clrt::read_png(path), Contains(path));

  const Bytes good = read_bytes(fixture("rgb16.png"));
  write_bytes(path, Bytes(good.begin(), good.begin() + 50));
  CHECK_THROWS_WITH(clrt::read_png(path), Contains(path));
  CHECK_THROWS_AS(clrt::read_png(dir.file("missing.png")), ImageError);
}

namespace {

constexpr std::size_t kAfterIhdr = 8 + 25;  // signature, then IHDR's length, type, 13 bytes, CRC

// A 3x2 PNG as clrt writes it, with `chunks` inserted straight after IHDR.
std::string png_with_chunks(const ScratchDir& dir, const Bytes& chunks) {
  const std::string path = dir.file("chunks.png");
  clrt::write_image(path, Rgba8Image{3, 2, {Bytes(24, 255)}});
  Bytes file = read_bytes(path);
  file.insert(file.begin() + kAfterIhdr, chunks.begin(), chunks.end());
  write_bytes(path, file);
  return path;
}

}  // namespace

TEST_CASE("PNG records a placement in a clrt:placement text chunk before the image data",
          "[image][png][placement]") {
  ScratchDir dir;
  const std::string path = dir.file("tile.png");
  clrt::write_image(path, clrt::FloatImage(3, 2, std::vector<float>(18, 0.5f),
                                           clrt::Placement{64, 30, 256, 128}));
  const Bytes file = read_bytes(path);
  const Bytes chunk = text_chunk("clrt:placement", "64,30 3x2 of 256x128");
  const auto found = std::search(file.begin(), file.end(), chunk.begin(), chunk.end());
  REQUIRE(found != file.end());
  const Bytes idat = bytes_of("IDAT");
  CHECK(found < std::search(file.begin(), file.end(), idat.begin(), idat.end()));

  const Rgba8Image back = clrt::read_png(path);
  CHECK(back.placement == clrt::Placement{64, 30, 256, 128});
  Bytes grey(24, 128);  // 0.5 quantises to 128; alpha 255
  for (std::size_t alpha = 3; alpha < grey.size(); alpha += 4) grey[alpha] = 255;
  CHECK(back.frames == std::vector<Bytes>{grey});
  CHECK(clrt::info_text(clrt::read_image_info(path)) ==
        "format: PNG\nwidth: 3\nheight: 2\nframes: 1\nchannels: RGB\nsamples: 8-bit\n"
        "placement: 64,30 3x2 of 256x128\ninterlace: none\ncolour space: sRGB\n");
}

TEST_CASE("PNG without a placement, or with a whole-frame one, has no text chunk",
          "[image][png][placement]") {
  ScratchDir dir;
  const std::string whole = dir.file("whole.png"), plain = dir.file("plain.png");
  const std::vector<float> grey(18, 0.25f);
  clrt::write_image(whole, clrt::FloatImage(3, 2, grey, clrt::Placement{0, 0, 3, 2}));
  clrt::write_image(plain, clrt::FloatImage(3, 2, grey));
  CHECK(read_bytes(whole) == read_bytes(plain));
  CHECK_FALSE(clrt::read_png(plain).placement);
  CHECK(clrt::read_image_info(plain).placement == std::nullopt);
}

TEST_CASE("PNG placement chunks are read strictly", "[image][png][placement]") {
  ScratchDir dir;
  const auto placement_of = [&](const Bytes& chunks) {
    return clrt::read_png(png_with_chunks(dir, chunks)).placement;
  };
  const auto error_of = [&](const Bytes& chunks) {
    const std::string path = png_with_chunks(dir, chunks);
    try {
      clrt::read_png(path);
    } catch (const ImageError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const std::string key = "clrt:placement";
  CHECK(placement_of(text_chunk(key, "1,2 3x2 of 10x10")) == clrt::Placement{1, 2, 10, 10});
  CHECK(placement_of(text_chunk(key, "0,0 3x2 of 3x2")) == std::nullopt);
  CHECK(placement_of(text_chunk("Comment", "1,2 3x2 of 10x10")) == std::nullopt);
  CHECK_THAT(error_of(text_chunk(key, "1,2 4x2 of 10x10")),
             Contains("chunks.png") && Contains("for a 4x2 image, but the image is 3x2"));
  CHECK_THAT(error_of(text_chunk(key, "8,2 3x2 of 10x10")), Contains("does not fit"));
  CHECK_THAT(error_of(text_chunk(key, "01,2 3x2 of 10x10")), Contains("not of the form"));
  CHECK_THAT(error_of(text_chunk(key, "1,2 3x2 of 10x10 ")), Contains("not of the form"));
  CHECK_THAT(error_of(text_chunk(key, "1,2 3x2 of 99999999999x10")), Contains("not of the form"));
  CHECK_THAT(error_of(text_chunk(key, "1,2 3x2 of 3000000000x10")), Contains("above"));
  CHECK_THAT(error_of(concat({text_chunk(key, "1,2 3x2 of 10x10"),
                              text_chunk(key, "1,2 3x2 of 10x10")})),
             Contains("appears twice"));
  Bytes damaged = text_chunk(key, "1,2 3x2 of 10x10");
  damaged.back() ^= 1;
  CHECK_THAT(error_of(damaged), Contains("not a readable PNG") && Contains("CRC"));
}

TEST_CASE("PNG info describes colour types and bit depths as stored", "[image][png]") {
  const clrt::ImageInfo rgb16 = clrt::read_image_info(fixture("rgb16.png"));
  CHECK(rgb16.channels == "RGB");
  CHECK(rgb16.samples == "16-bit");
  CHECK(rgb16.details == decltype(rgb16.details){{"interlace", "none"},
                                                 {"colour space", "unspecified"}});
  const clrt::ImageInfo palette = clrt::read_image_info(fixture("palette2.png"));
  CHECK(palette.channels == "palette with transparency (tRNS)");
  CHECK(palette.samples == "2-bit indices");
  CHECK(clrt::read_image_info(fixture("gray_alpha8.png")).channels == "grey, alpha");
  CHECK(clrt::read_image_info(fixture("gray1.png")).samples == "1-bit");
}

TEST_CASE("a chunk longer than the file is refused before libpng allocates it", "[image][png]") {
  // The fuzzer's 45-byte file whose second chunk declares 1347179589 bytes: libpng allocated
  // 1.3 GB for it before finding the file too short.
  const std::string path =
      std::string(CLRT_SOURCE_DIR) + "/tests/fuzz/regressions/fuzz_image_png/chunk-length-1347179589.png";
  CHECK_THROWS_WITH(clrt::read_png(path),
                    Contains("a chunk declares 1347179589 bytes, more than the file has left"));
}

TEST_CASE("a PNG larger than clrt renders is refused before its image is allocated",
          "[image][png]") {
  // IHDR rewritten (with its CRC) to a side beyond 65536 (libpng: "Invalid IHDR data", past the
  // user limit), then to 20000 x 20000 (more pixels than 2^28): the file stays 3x2 pixels of
  // data, so any allocation would be for nothing.
  ScratchDir dir;
  const std::string path = dir.file("forged.png");
  clrt::write_image(path, Rgba8Image{3, 2, {Bytes(24, 255)}});
  const Bytes valid = read_bytes(path);
  for (const auto& [w, h, message] : {std::tuple<std::uint32_t, std::uint32_t, const char*>{
                                          65537, 2, "Invalid IHDR data"},
                                      {20000, 20000, "20000x20000 pixels are more than clrt reads"}}) {
    INFO(w << "x" << h);
    Bytes file = valid;
    const Bytes size = concat({u32_be(w), u32_be(h)});
    std::copy(size.begin(), size.end(), file.begin() + 16);  // after the signature, length, "IHDR"
    const Bytes ihdr(file.begin() + 12, file.begin() + 29);  // type and 13 bytes of data
    const Bytes crc = u32_be(png_crc(ihdr));
    std::copy(crc.begin(), crc.end(), file.begin() + 29);
    write_bytes(path, file);
    CHECK_THROWS_WITH(clrt::read_png(path), Contains(message));
  }
}
