#include "cli/picture_options.hpp"

#include "cli/decimal_number.hpp"
#include "cli/word_choice.hpp"
#include "render/usage_error.hpp"

namespace clrt {

void add_picture_options(CLI::App& app, CliOptions& o) {
  app.add_option("--exposure", o.exposure,
                 "scale every value by 2^STOPS before the tone curve, in 8-bit outputs "
                 "(default 0)")
      ->check(decimal_number());
  app.add_option_function<std::string>(
         "--tonemap", [&](const std::string& name) { o.tonemap = *tone_curve_from_name(name); },
         "the tone curve of 8-bit outputs: clamp (default: values above 1 are white) or filmic "
         "(highlights roll off)")
      ->transform(word_choice(tone_curve_names()));
}

DisplayTransform display_transform(const CliOptions& cli, RenderMode mode) {
  DisplayTransform display;
  display.exposure = cli.exposure;
  display.curve = cli.tonemap;
  display.srgb = mode == RenderMode::Path;
  return display;
}

void check_picture_output(const CliOptions& cli, const ImageOutput& output) {
  if (output.path.empty() || !holds_floats(output.format)) return;
  if (cli.exposure == 0 && cli.tonemap == ToneCurve::Clamp) return;
  const std::string name = output.is_stdout() ? "standard output's " + format_name(output.format)
                                              : output.path;
  throw UsageError("--exposure and --tonemap shape 8-bit images (png, ppm, fsf); " + name +
                   " keeps the render's linear values (clrt-img convert --exposure ... makes "
                   "an 8-bit image of it later)");
}

bool renders_bytes(const ImageOutput& output, const DisplayTransform& display) {
  return !holds_floats(output.format) && display.identity();
}

}  // namespace clrt
