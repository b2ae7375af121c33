// clrt-fsfconv: a thin command line over clrt_image.
//   clrt-fsfconv IN OUT [--frame N]   convert by extension (.fsf, .png, .ppm; OUT may also be .pfm)
//   clrt-fsfconv --info FILE.fsf      print the FSF header
// Exit status: 0 success, 1 a file could not be read or written, 2 a usage error.
#include <CLI/CLI.hpp>
#include <climits>
#include <iostream>
#include <optional>
#include <string>

#include "image/image.hpp"

namespace {

struct Options {
  std::string input, output, info;
  std::optional<int> frame;
};

void convert(const Options& options) {
  clrt::Rgba8Image image = clrt::read_image(options.input);
  if (options.frame) image = clrt::select_frame(image, *options.frame);
  clrt::write_image(options.output, image);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Convert images between FSF, PNG and PPM by their extensions, or summarise an FSF file.",
      "clrt-fsfconv"};
  Options options;
  CLI::Option* input = app.add_option("input", options.input, "image to read (.fsf, .png, .ppm)");
  CLI::Option* output =
      app.add_option("output", options.output, "image to write (.fsf, .png, .ppm, .pfm)");
  CLI::Option* info = app.add_option("--info", options.info,
                                     "print the header of an FSF file instead of converting")
                          ->excludes(input)
                          ->excludes(output);
  app.add_option(
         "--frame", options.frame,
         "convert only this frame of an animation, counted from 0 (default: all frames into FSF, "
         "frame 0 into the other formats)")
      ->check(CLI::Range(0, INT_MAX))
      ->excludes(info);
  try {
    app.parse(argc, argv);
    if (options.info.empty() && options.output.empty())
      throw CLI::ValidationError("give INPUT and OUTPUT, or --info FILE");
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  }

  try {
    if (!options.info.empty())
      std::cout << clrt::fsf_summary(clrt::read_fsf_header(options.info));
    else
      convert(options);
  } catch (const std::exception& error) {
    std::cerr << "clrt-fsfconv: error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
