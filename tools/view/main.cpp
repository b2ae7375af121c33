// clrt-view: a window on the images clrt writes, or on a render as it fills in
// (docs/viewer.md). Exit status: 0 when the window is closed, 1 an image that cannot be read or
// a window that cannot be opened, 2 a usage error.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <limits>
#include <optional>

#include "cli/decimal_number.hpp"
#include "cli/tool_command_line.hpp"
#include "cli/whole_number.hpp"
#include "image/image_info.hpp"
#include "memory_need.hpp"
#include "cli/word_choice.hpp"
#include "window.hpp"

namespace {

struct ViewOptions {
  std::string a, b;
  double exposure = 0, gamma = 1, fps = 25;
  std::string tonemap = "clamp";
  bool srgb = false, linear = false, gamma_given = false;
  int frame = 1;
  std::optional<double> zoom;
  bool pause = false, side_by_side = false, difference = false, show_b = false, preview = false;
};

void add_options(CLI::App& app, ViewOptions& options) {
  app.add_option("image", options.a, "image to show: .fsf .png .ppm .pfm .exr");
  app.add_option("other", options.b, "a second image of the same size, to compare with the first");
  app.add_option("--exposure", options.exposure, "stops to scale the values by (default 0)");
  app.add_option("--gamma", options.gamma,
                 "show value^(1/gamma) (default 1: the bytes clrt's PNG holds)")
      ->check(clrt::decimal_number(0.1, 10.0))
      ->each([&options](const std::string&) { options.gamma_given = true; });
  app.add_option("--tonemap", options.tonemap,
                 "the tone curve: clamp (default: values above 1 are white) or filmic")
      ->transform(clrt::word_choice(clrt::tone_curve_names()));
  CLI::Option* const srgb = app.add_flag(
      "--srgb", options.srgb,
      "encode with sRGB's curve instead of the gamma, as clrt --mode path writes its 8-bit "
      "images (the default for PFM, EXR and --preview, unless --gamma or --linear)");
  app.add_flag("--linear", options.linear,
               "show a PFM's or EXR's values as they are, without sRGB's curve (a Whitted render's)")
      ->excludes(srgb);
  app.add_option("--frame", options.frame, "the frame to start at, from 1")
      ->transform(clrt::whole_number(1, std::numeric_limits<int>::max()));
  app.add_option("--fps", options.fps, "frames per second of an animation (default 25)")
      ->check(clrt::decimal_number(0.1, 1000.0));
  app.add_flag("--pause", options.pause, "start an animation paused");
  app.add_option("--zoom", options.zoom,
                 "screen pixels per image pixel, any factor from 1/64 to 256 (0.5 halves the "
                 "image; default: what fits the screen, docs/viewer.md)")
      ->check(clrt::decimal_number(clrt::view::kMinZoom, clrt::view::kMaxZoom));
  app.add_flag("--side-by-side", options.side_by_side, "two images: show them side by side");
  app.add_flag("--difference", options.difference, "two images: show their difference");
  app.add_flag("--flip", options.show_b, "two images: start on the second");
  app.add_flag("--preview", options.preview,
               "show the render clrt --preview streams on standard input");
}

// Refuses, from the headers alone, images whose showing the memory cannot hold: each file with
// its decoded pixels, every frame again as floats, and with two images their difference's
// frames (a PNG of under a megabyte may declare 2^28 pixels: gigabytes once decoded).
void check_view_memory(const std::string& a, const std::string& b) {
  using clrt::img::pixels_of;
  clrt::img::MemoryNeed need;
  const clrt::ImageInfo first = clrt::read_image_info(a);
  need.add_read(a, first);
  need.add_float_frames(pixels_of(first), first.frames);
  if (!b.empty()) {
    const clrt::ImageInfo second = clrt::read_image_info(b);
    need.add_read(b, second);
    need.add_float_frames(pixels_of(second), second.frames);
    need.add_float_frames(pixels_of(first), std::max(first.frames, second.frames));
  }
  clrt::img::check_memory(need, "showing " + a + (b.empty() ? "" : " and " + b));
}

int view(const ViewOptions& options) {
  using namespace clrt::view;
  if (options.preview != options.a.empty())
    throw CLI::ValidationError(options.preview ? "--preview reads standard input: name no image"
                                               : "name an image to show");
  if (!options.b.empty() && options.preview)
    throw CLI::ValidationError("--preview shows one render: name no image");
  std::optional<PreviewFeed> feed;
  ViewSources sources;
  if (options.preview) {
    feed.emplace(0);
    sources.width = feed->width();
    sources.height = feed->height();
    sources.linear = true;
    sources.a.emplace_back(sources.width, sources.height,
                           std::vector<float>(3 * std::size_t(sources.width) * sources.height));
  } else {
    check_view_memory(options.a, options.b);
    const clrt::AnyImage a = clrt::read_any_image(options.a);
    if (options.b.empty()) {
      sources = make_sources(a, nullptr);
    } else {
      const clrt::AnyImage b = clrt::read_any_image(options.b);
      sources = make_sources(a, &b);
    }
  }
  ViewState state;
  state.tone = {options.exposure, options.gamma, *clrt::tone_curve_from_name(options.tonemap),
                options.srgb || (sources.linear && !options.linear && !options.gamma_given)};
  state.side_by_side = options.side_by_side;
  state.show_difference = options.difference;
  state.flipped = options.show_b ? Picture::B : Picture::A;
  state.frame = std::min(options.frame, sources.frame_count()) - 1;
  Playback playback;
  playback.fps = options.fps;
  playback.playing = !options.pause;
  const ViewNames names{options.preview ? "clrt --preview" : options.a, options.b};
  return run_window(sources, names, state, options.zoom, playback, feed ? &*feed : nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Show the images clrt writes (FSF animations, PNG, PPM, PFM, OpenEXR), compare two, "
               "or watch a render fill in (clrt --preview).",
               "clrt-view"};
  clrt::identify_tool(
      app, {"docs/viewer.md",
            {},
            {{"0", "the window was closed (or q), or --help or --version"},
             {"1", "an image that cannot be read, two images of different sizes, images the memory "
                   "cannot hold, or no window (no display)"},
             {"2", "a usage error"}},
            {{"clrt-view c.exr", "a render's radiance through sRGB, as clrt's PNG of it shows it"},
             {"clrt-view turn.fsf --fps 12", "play an animation"},
             {"clrt-view a.pfm b.pfm --difference", "compare two images: Tab flips, d shows the difference"},
             {"clrt scenes/reflect.ray --preview", "watch a render fill in"}}});
  ViewOptions options;
  add_options(app, options);
  if (const auto status = clrt::parse_tool_arguments(app, argc, argv)) return *status;
  try {
    return view(options);
  } catch (const CLI::ValidationError& error) {
    std::cerr << "clrt-view: error: " << error.what() << "\n";
    return 2;
  } catch (const clrt::NotAFileError& error) {
    std::cerr << "clrt-view: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "clrt-view: error: " << error.what() << "\n";
    return 1;
  }
}
