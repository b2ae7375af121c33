// clrt-img info end to end, for every format.
#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "run_tool.hpp"

using clrt::FloatImage;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

TEST_CASE("info prints each format's header, the frames and the placement", "[img][info]") {
  ScratchDir dir;
  const FloatImage tile(3, 2, std::vector<float>(18, 0.5f), clrt::Placement{2, 4, 10, 8});
  const std::string fsf = dir.file("a.fsf"), png = dir.file("a.png"), ppm = dir.file("a.ppm"),
                    pfm = dir.file("a.pfm"), exr = dir.file("a.exr");
  clrt::write_image(fsf, Rgba8Image{3, 2, {Bytes(24, 7), Bytes(24, 8)}});
  clrt::write_image(png, tile);
  clrt::write_image(ppm, tile);
  clrt::write_image(pfm, tile);
  clrt::write_image(exr, tile, {clrt::ExrPixel::Float});
  const ToolResult result = run_img(dir, "info " + quoted(fsf) + " " + quoted(png) + " " +
                                             quoted(ppm) + " " + quoted(pfm) + " " + quoted(exr));
  CHECK(result.status == 0);
  CHECK(result.err.empty());
  const std::string common = "width: 3\nheight: 2\n";
  CHECK(result.out_text() ==
        "file: " + fsf + "\nformat: FSF\n" + common +
            "frames: 2\nchannels: RGBA\nsamples: 8-bit\nplacement: none (FSF cannot record one)\n"
            "byte order: little-endian\nbytes: 64\n\n"
            "file: " + png + "\nformat: PNG\n" + common +
            "frames: 1\nchannels: RGB\nsamples: 8-bit\nplacement: 2,4 3x2 of 10x8\n"
            "interlace: none\ncolour space: sRGB\n\n"
            "file: " + ppm + "\nformat: PPM\n" + common +
            "frames: 1\nchannels: RGB\nsamples: 8-bit\nplacement: none (PPM cannot record one)\n"
            "encoding: binary (P6)\nmaxval: 255\n\n"
            "file: " + pfm + "\nformat: PFM\n" + common +
            "frames: 1\nchannels: RGB\nsamples: 32-bit float\n"
            "placement: none (PFM cannot record one)\nbyte order: little-endian\nscale: -1.0\n\n"
            "file: " + exr + "\nformat: EXR\n" + common +
            "frames: 1\nchannels: B, G, R\nsamples: 32-bit float\nplacement: 2,4 3x2 of 10x8\n"
            "data window: (2, 4) - (4, 5)\ndisplay window: (0, 0) - (9, 7)\n"
            "compression: ZIP\nstorage: scanlines\n");
}

TEST_CASE("info of a whole image says so, bad files fail with 1, bad names with 2", "[img][info]") {
  ScratchDir dir;
  const std::string png = dir.file("whole.png");
  clrt::write_image(png, FloatImage(1, 1, {0, 0, 0}));
  ToolResult result = run_img(dir, "info " + quoted(png));
  CHECK(result.status == 0);
  CHECK_THAT(result.out_text(), Contains("placement: none (the whole frame)\n"));

  const std::string bad = dir.write("bad.exr", "not an EXR");
  result = run_img(dir, "info " + quoted(png) + " " + quoted(bad));
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("clrt-img: error: ") && Contains(bad));
  result = run_img(dir, "info " + quoted(png) + " " + quoted(dir.file("a.tiff")));
  CHECK(result.status == 2);
  CHECK(result.out.empty());
  CHECK(run_img(dir, "info").status == 2);
}
