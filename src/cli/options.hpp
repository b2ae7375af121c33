// The clrt command line.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/animation_options.hpp"
#include "cli/docs/tool_manual.hpp"
#include "cli/region_options.hpp"
#include "image/image.hpp"
#include "render/render_options.hpp"

namespace CLI {
class App;
}

namespace clrt {

enum class StatsFormat { None, Text, Json };

struct CliOptions {
  std::string scene;
  std::string outfile;  // empty: the scene's name with .png, in the current directory
  bool no_write = false;  // --no-write or -o none: render and report, write nothing
  std::optional<ImageFormat> format;    // --format: the output's format, else its extension
  ExrPixel exr_pixel = ExrPixel::Half;  // --exr-pixel
  double exposure = 0;                  // --exposure: stops, for 8-bit outputs
  ToneCurve tonemap = ToneCurve::Clamp;  // --tonemap: the curve of 8-bit outputs
  std::optional<double> max_sample_value;  // --max-sample-value: the firefly clamp
  bool glossy = false;                     // --glossy: blurred reflections in trace mode
  std::optional<int> width, height, samples, max_depth;
  std::optional<RenderMode> mode;
  std::uint32_t seed = 0;
  std::uint32_t wavefront = 0;  // 0: per device class, see device_profile.cpp
  std::size_t local_size = 0;   // 0: per device class
  std::uint32_t lanes = 0;      // 0: per device class
  std::optional<unsigned> threads;  // PoCL's CPU threads
  std::string integrator = "wavefront";  // a name of integrator_table()
  bool shade_by_class = false;
  RegionRequest region;
  AnimationRequest animation;
  std::string device = "cpu";
  bool list_devices = false;
  StatsFormat stats = StatsFormat::None;
  bool quiet = false;
  bool preview = false;  // --preview: a clrt-view window shows the render as it fills in
  bool resume = false;   // --resume: go on from the output's resume state, and keep it
  std::optional<std::string> dump_scene;  // --dump-scene: where the scene goes as JSON, no render
};

// What parsing decided: run with the options, or exit now with a code (after --help,
// --version or a usage error, whose message has been printed).
struct ParseResult {
  CliOptions options;
  std::optional<int> exit_code;
};

// clrt's: docs/cli.md, its exit statuses and examples.
ToolManual clrt_manual();

// A program that takes clrt's options, and what it changes of them, so that its --help lists
// exactly what it accepts.
struct ProgramOptions {
  std::string name = "clrt";
  bool animation = true;  // --frames, --orbit, --frame-range
  bool preview = true;    // --preview
  bool resume = true;     // --resume
  bool dump_scene = true; // --dump-scene
  std::function<void(CLI::App&)> add_own_options;  // e.g. clrt-mpi's --tile
  ToolManual manual = clrt_manual();  // the page --help points at, and the man page's sections
};

// --stats and --stats-format as given, before they are read into CliOptions::stats.
struct StatsRequest {
  bool flag = false;
  std::string format = "text";
};

// The parser itself, filling `o` and `stats` when it parses: what --help lists, and what the
// man page and the shell completion are generated from (cli/docs/).
std::unique_ptr<CLI::App> clrt_command_line(CliOptions& o, StatsRequest& stats,
                                            const ProgramOptions& program = {});

ParseResult parse_command_line(int argc, char** argv);
// The words after the program's name; `print` false: no message (the MPI ranks but the first,
// which prints it).
ParseResult parse_arguments(std::vector<std::string> args, bool print,
                            const ProgramOptions& program = {});

// The scene's settings overridden by whatever the command line gave. Throws UsageError for a
// region that does not fit the image.
RenderOptions resolve_render_options(const CliOptions& cli, const Scene& scene);

// The output path: --outfile, or SCENE's stem + "." + the --format name (default png).
std::string output_path(const CliOptions& cli);

}  // namespace clrt
