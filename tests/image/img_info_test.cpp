// clrt-img info end to end, for every format.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <string>
#include <vector>

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

TEST_CASE("every command refuses at once, exit 2, an input that is a FIFO, a device or a folder",
          "[img][info][convert][diff][stitch]") {
  ScratchDir dir;
  const std::string good = dir.file("good.png");
  clrt::write_image(good, FloatImage(1, 1, {0, 0, 0}));
  for (const std::string extension : {".png", ".pfm", ".exr", ".ppm", ".fsf"}) {
    const std::string fifo = dir.file("fifo" + extension), folder = dir.file("folder" + extension);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    REQUIRE(::mkdir(folder.c_str(), 0700) == 0);
    const std::string out = quoted(dir.file("out.png"));
    for (const std::string& input : {fifo, folder}) {
      const std::string in = quoted(input);
      std::vector<std::string> commands{"info " + in, "convert " + in + " " + out,
                                        "diff " + quoted(good) + " " + in};
      // Tiles are PNG or EXR: stitch refuses the other names before reading them.
      if (extension == ".png" || extension == ".exr")
        commands.push_back("stitch " + out + " " + in);
      for (const std::string& command : commands) {
        // Without the check, opening the FIFO waits for a writer that never comes: timeout's
        // 124 then fails the test instead of hanging it.
        const ToolResult result =
            run_tool(dir, "timeout", "20 " + quoted(CLRT_IMG) + " " + command);
        INFO(command);
        CHECK(result.status == 2);
        const std::string why = input == fifo ? "it is not a regular file" : "it is a folder";
        CHECK(result.err == "clrt-img: error: cannot read " + input + ": " + why + "\n");
      }
    }
    // A device, with an extension through a link: the link is followed to /dev/zero.
    const std::string device = dir.file("zero" + extension);
    REQUIRE(::symlink("/dev/zero", device.c_str()) == 0);
    const ToolResult result =
        run_tool(dir, "timeout", "20 " + quoted(CLRT_IMG) + " info " + quoted(device));
    CHECK(result.status == 2);
    CHECK(result.err == "clrt-img: error: cannot read " + device + ": it is not a regular file\n");
  }
}
