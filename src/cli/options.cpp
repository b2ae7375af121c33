#include "cli/options.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>
#include <utility>

#include "cli/argument_words.hpp"
#include "cli/decimal_number.hpp"
#include "cli/picture_options.hpp"
#include "cli/tool_command_line.hpp"
#include "cli/whole_number.hpp"
#include "cli/word_choice.hpp"
#include "math/number_fields.hpp"
#include "render/integrator_names.hpp"

#include "scene/limits.hpp"

namespace clrt {
namespace {

constexpr const char* kNoOutputPath = "none";

// "640x480" -> width, height; CLI11 reports the returned message as a usage error.
std::string parse_resolution(const std::string& text, CliOptions& o) {
  const auto size = read_number_fields(text, {"#x#", 6, false, true});
  if (!size) return "--resolution takes WIDTHxHEIGHT, e.g. 1280x720";
  o.width = static_cast<int>((*size)[0]);
  o.height = static_cast<int>((*size)[1]);
  if (*o.width < 1 || *o.height < 1) return "--resolution: width and height must be at least 1";
  return {};
}

void add_output_options(CLI::App& app, CliOptions& o) {
  app.add_option("-o,--outfile", o.outfile,
                 "output image; the extension picks the format: .png .ppm .fsf .pfm .exr; "
                 "- writes to standard output (needs --format), none writes nothing "
                 "(default: SCENE's name with .png)");
  app.add_flag("--no-write", o.no_write, "render and report, but write no image (as -o none)");
  app.add_option_function<std::string>(
         "--format", [&](const std::string& name) { o.format = format_from_name(name); },
         "the output's format, whatever its extension: png ppm fsf pfm exr")
      ->transform(word_choice(format_names()));
  app.add_option_function<std::string>(
         "--exr-pixel",
         [&](const std::string& pixel) {
           o.exr_pixel = CLI::detail::to_lower(pixel) == "float" ? ExrPixel::Float : ExrPixel::Half;
         },
         "EXR channels: half (default) or float")
      ->transform(word_choice({"half", "float"}));
  add_picture_options(app, o);
}

void add_image_options(CLI::App& app, CliOptions& o) {
  app.add_option_function<std::string>(
      "--resolution",
      [&](const std::string& s) {
        const std::string error = parse_resolution(s, o);
        if (!error.empty()) throw CLI::ValidationError(error);
      },
      "image size WxH (overrides the scene's `resolution`)");
  for (const auto& [name, pbrt_name, whole, field, help] :
       {std::tuple{"--pixel-bounds", "--pixelbounds", true, &o.region.pixel_bounds,
                   "render only pixels x0,x1,y0,y1 (half-open; four words also do)"},
        std::tuple{"--crop-window", "--cropwindow", false, &o.region.crop_window,
                   "render only the fractions x0,x1,y0,y1 of the image (four words also do)"}})
    app.add_option_function<std::string>(
        std::string(name) + "," + pbrt_name,
        [name = std::string(name), whole = whole, field = field](const std::string& text) {
          const std::string error = parse_region_numbers(text, whole, *field);
          if (!error.empty()) throw CLI::ValidationError(name + " " + error);
        },
        help);
}

void add_shading_options(CLI::App& app, CliOptions& o) {
  app.add_option("--spp", o.samples, "camera samples per pixel (overrides `samples`)")
      ->transform(whole_number(1, limits::kMaxSamples));
  app.add_option("--max-depth", o.max_depth,
                 "deepest reflection/refraction bounce (overrides `maxdepth`)")
      ->transform(whole_number(0, limits::kMaxDepth));
  static const std::map<std::string, RenderMode> modes{
      {"trace", RenderMode::Trace}, {"cast", RenderMode::Cast}, {"path", RenderMode::Path}};
  app.add_option_function<std::string>(
         "--mode", [&](const std::string& mode) { o.mode = modes.at(CLI::detail::to_lower(mode)); },
         "trace (Whitted: shadows, reflection, refraction), cast (local shading only) or path "
         "(Monte Carlo path tracing: indirect light, docs/path-tracing.md)")
      ->transform(word_choice({"trace", "cast", "path"}));
  app.add_option("--max-sample-value", o.max_sample_value,
                 "scale every camera sample whose largest channel exceeds this down to it before "
                 "samples are averaged: fewer fireflies, a biased image (default: no clamp)")
      ->check(positive_decimal_number());
  app.add_flag("--glossy", o.glossy,
               "trace mode: blur every reflection by the material's Phong exponent (distribution "
               "ray tracing's glossy reflection; it converges with --spp)");
  app.add_option("--seed", o.seed, "seed of the random numbers (jitter, area lights)")
      ->transform(seed_number())
      ->capture_default_str();
}

void add_animation_options(CLI::App& app, CliOptions& o) {
  app.add_option("--frames", o.animation.frames,
                 "render N frames of a turntable around lookat (FSF: one file; else name-0001.png...)")
      ->transform(whole_number(1, 1 << 24));
  app.add_option("--orbit", o.animation.orbit_degrees,
                 "degrees the camera turns over all the frames (default 360)")
      ->check(decimal_number());
  app.add_option("--frame-range", o.animation.frame_range,
                 "render frames FIRST:LAST only (from 1, inclusive), e.g. a farm's share");
}

void add_device_options(CLI::App& app, CliOptions& o) {
  app.add_option("--device", o.device,
                 "cpu, gpu, all, P:D (platform:device index), NAME:D (device D of the platform "
                 "named NAME: pocl:0) or part of a device or platform name")
      ->capture_default_str();
  app.add_flag("--list-devices", o.list_devices, "list the OpenCL devices and exit");
  app.add_option("--threads,--nthreads", o.threads,
                 "CPU threads of PoCL's or Intel's CPU device (default: every core)")
      ->transform(whole_number(1, 4096));
  app.add_option_function<std::string>(
         "--integrator", [&](const std::string& name) { o.integrator = *parse_integrator(name); },
         integrator_summaries() + " (every integrator renders the same image)")
      ->transform(word_choice(integrator_names()));
  app.add_option("--wavefront", o.wavefront,
                 "rays in flight per queue: device memory grows with it "
                 "(default: 16384 on CPU devices, 1048576 on others)")
      ->transform(whole_number(1 << 10, 1 << 26));
  app.add_option_function<std::string>(
         "--shade-order",
         [&](const std::string& order) { o.shade_by_class = CLI::detail::to_lower(order) == "class"; },
         "queue (default): the wavefront shades each pass's hits in queue order; class: misses, "
         "local-only surfaces, then mirrors and glass, one launch each (same image)")
      ->transform(word_choice({"queue", "class"}));
  app.add_option("--lanes", o.lanes,
                 "waves in flight per device, each with its own queues (default: per device class)")
      ->transform(whole_number(1, 16));
  app.add_option("--local-size", o.local_size,
                 "work-items per work-group for every kernel (default: per device class)")
      ->transform(whole_number(1, 1024));
}

}  // namespace

ToolManual clrt_manual() {
  return {"docs/cli.md",
          {},
          {{"0", "the image was written (or, with --no-write, rendered), or --help or --version"},
           {"1", "a failure at run time: no OpenCL device, a kernel that does not build, memory the "
                 "device or the machine does not have, a write that fails"},
           {"2", "a usage or scene error (FILE:LINE:COLUMN: error: ...), or an output that cannot be "
                 "written where it is named, found before any work"},
           {"128 + N", "ended by signal N: 130 for SIGINT (Ctrl-C), 143 for SIGTERM; no temporary or "
                       "partial output is left"}},
          {{"clrt scenes/reflect.ray -o reflect.png", "render one image; the extension chooses the "
                                                      "format (.png .ppm .fsf .pfm .exr)"},
           {"clrt scenes/cornell.ray --mode path --spp 256 -o c.png", "path tracing: indirect light"},
           {"clrt --frames 24 --orbit 90 scenes/reflect.ray -o turn.fsf", "a turntable animation"},
           {"clrt scenes/reflect.ray --preview", "watch the render fill in, in clrt-view"},
           {"clrt --list-devices", "the OpenCL devices, as P:D for --device"}}};
}

ParseResult parse_command_line(int argc, char** argv) {
  return parse_arguments({argv + 1, argv + argc}, true);
}

std::unique_ptr<CLI::App> clrt_command_line(CliOptions& o, StatsRequest& stats,
                                            const ProgramOptions& program) {
  auto app = std::make_unique<CLI::App>(
      program.name + ": a wavefront OpenCL ray tracer for .ray and .nff scenes", program.name);
  ToolManual manual = program.manual;
  manual.positional_extensions = {"ray", "RAY", "nff", "NFF"};
  identify_tool(*app, manual);
  app->add_option("scene", o.scene, "the .ray or .nff scene to render");
  // --help lists the options in groups, in the order a render is set up.
  using AddOptions = void (*)(CLI::App&, CliOptions&);
  std::vector<std::pair<const char*, AddOptions>> groups = {{"Scene and image", add_image_options},
                                                            {"Rendering", add_shading_options},
                                                            {"Devices", add_device_options},
                                                            {"Output", add_output_options}};
  if (program.animation) groups.emplace_back("Animation", add_animation_options);
  for (const auto& [group, add] : groups) {
    app->option_defaults()->group(group);
    add(*app, o);
  }
  if (program.preview)
    app->add_flag("--preview", o.preview,
                  "show the render as it fills in, in a clrt-view window (docs/viewer.md)")
        ->group("Output");
  if (program.resume)
    app->add_flag("--resume", o.resume,
                  "go on from OUTPUT.clrt-resume, the state a stopped render (Ctrl-C) leaves, or "
                  "add samples to a finished one (--spp N); keep the state when done "
                  "(docs/cli.md#stopping-and-resuming-a-render)")
        ->group("Output");
  if (program.dump_scene)
    app->add_option("--dump-scene", o.dump_scene,
                    "write the scene as clrt reads it to FILE as JSON (- for standard output) and "
                    "exit without rendering or starting OpenCL (docs/scene-json.md)")
        ->type_name("FILE")
        ->group("Output");
  if (program.add_own_options) {
    app->option_defaults()->group(program.name);
    program.add_own_options(*app);
  }
  app->option_defaults()->group("Diagnostics");
  app->add_flag("--stats", stats.flag,
                "print rays by kind, times and queue sizes to stdout (--stats=json: as JSON)");
  app->add_option("--stats-format", stats.format, "text or json")
      ->transform(word_choice({"text", "json"}));
  app->add_flag("-q,--quiet", o.quiet, "print nothing but errors (no device line, no progress)");
  return app;
}

ParseResult parse_arguments(std::vector<std::string> args, bool print,
                            const ProgramOptions& program) {
  ParseResult result;
  CliOptions& o = result.options;
  StatsRequest stats;
  const std::unique_ptr<CLI::App> command_line = clrt_command_line(o, stats, program);
  CLI::App& app = *command_line;
  result.exit_code =
      parse_tool_arguments(app, regular_argument_words(std::move(args)), print);
  if (result.exit_code) return result;
  try {
    if (stats.flag || app.count("--stats-format"))
      o.stats = stats.format == "json" ? StatsFormat::Json : StatsFormat::Text;
    if (o.scene.empty() && (!o.list_devices || o.dump_scene)) throw CLI::RequiredError("scene");
    if (o.dump_scene && o.dump_scene->empty())
      throw CLI::ValidationError("--dump-scene", "the output's name is empty");
    if (app.count("--outfile") && o.outfile.empty())
      throw CLI::ValidationError("-o", "the output's name is empty; -o none writes nothing");
    if (o.outfile == kNoOutputPath) o.no_write = true;
    if (o.outfile == kStdoutPath && !o.format)
      throw CLI::ValidationError("-o -", "standard output needs --format png|ppm|pfm|fsf|exr");
  } catch (const CLI::ParseError& e) {
    std::ostringstream silent;
    result.exit_code = (print ? app.exit(e) : app.exit(e, silent, silent)) == 0 ? 0 : 2;
  }
  return result;
}

RenderOptions resolve_render_options(const CliOptions& cli, const Scene& scene) {
  RenderOptions r = RenderOptions::from_scene(scene);
  if (cli.width) r.width = *cli.width;
  if (cli.height) r.height = *cli.height;
  if (cli.samples) r.samples = *cli.samples;
  if (cli.max_depth) r.max_depth = *cli.max_depth;
  if (cli.mode) r.mode = *cli.mode;
  if (cli.max_sample_value) r.max_sample_value = static_cast<float>(*cli.max_sample_value);
  r.glossy = cli.glossy;
  r.seed = cli.seed;
  r.wavefront = cli.wavefront;
  r.local_size = cli.local_size;
  r.lanes = cli.lanes;
  r.integrator = cli.integrator;
  r.shade_by_class = cli.shade_by_class;
  r.region = resolve_region(cli.region, r.width, r.height);
  return r;
}

std::string output_path(const CliOptions& cli) {
  if (!cli.outfile.empty()) return cli.outfile;
  return std::filesystem::path(cli.scene).stem().string() + "." +
         format_name(cli.format.value_or(ImageFormat::Png));
}

}  // namespace clrt
