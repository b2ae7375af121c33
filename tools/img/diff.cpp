// clrt-img diff A B: how far two renders of one frame are apart; exit 1 when a pixel differs by
// more than the threshold. --frame N picks frame N of both, --frame-a and --frame-b one side's
// (a still against an animation's frame).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>

#include "cli/decimal_number.hpp"
#include "command_line.hpp"
#include "image/compare.hpp"

namespace clrt::img {
namespace {

struct DiffOptions {
  std::string a, b, out;
  double threshold = 0;
  std::optional<int> frame, frame_a, frame_b;
};

std::string number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

std::string report(const ImageDifference& d, double threshold) {
  const std::string unit = d.floats ? "" : " (of 255)";
  return std::string("compared: R, G, B as ") +
         (d.floats ? "floats (differences in linear units)"
                   : "8-bit samples (differences in steps of 1/255)") +
         "\npixels: " + std::to_string(d.pixels) + "\ndiffering pixels: " +
         std::to_string(d.differing) + " (a channel differs by more than " + number(threshold) +
         ")\nlargest difference: " + number(d.largest) + unit + "\nPSNR: " + number(d.psnr) +
         " dB\n";
}

int diff(const DiffOptions& options) {
  input_format(options.a);
  input_format(options.b);
  std::optional<ImageOutput> out;
  if (!options.out.empty()) out = output_argument(options.out, std::nullopt);
  const std::optional<int> frame_a = options.frame ? options.frame : options.frame_a;
  const std::optional<int> frame_b = options.frame ? options.frame : options.frame_b;
  const AnyImage a = pick_frame(read_any_image(options.a), frame_a, options.a,
                                "--frame-a N (counted from 1; --frame N for both)");
  const AnyImage b = pick_frame(read_any_image(options.b), frame_b, options.b,
                                "--frame-b N (counted from 1; --frame N for both)");
  const ImageDifference difference = compare_images(a, b, options.threshold);
  std::cout << report(difference, options.threshold) << std::flush;
  if (out) write_image(*out, difference.difference);
  return difference.differing > 0 ? 1 : 0;
}

}  // namespace

void add_diff(CLI::App& app, Command& command) {
  auto options = std::make_shared<DiffOptions>();
  CLI::App* sub = app.add_subcommand(
      "diff", "compare two images of the same size; exit 1 when they differ beyond --threshold");
  sub->add_option("a", options->a, "first image")->required();
  sub->add_option("b", options->b, "second image")->required();
  sub->add_option("--threshold", options->threshold,
                  "largest channel difference still counted as equal: in steps of 1/255 for "
                  "8-bit comparisons, linear units for float ones (default 0)")
      ->check(clrt::decimal_number(0));
  sub->add_option("--out", options->out,
                  "write |A - B| per channel, scaled so the largest difference is white");
  CLI::Option* both = add_frame_option(*sub, "--frame", options->frame,
                                       "the frame to compare, in both images");
  // Naming a side's frame and both sides' at once would leave one of them unread: refused.
  both->excludes(add_frame_option(*sub, "--frame-a", options->frame_a, "the frame of A"));
  both->excludes(add_frame_option(*sub, "--frame-b", options->frame_b, "the frame of B"));
  sub->callback([&command, options] { command = [options] { return diff(*options); }; });
}

}  // namespace clrt::img
