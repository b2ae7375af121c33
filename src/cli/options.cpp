#include "cli/options.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <regex>

#include "scene/limits.hpp"

namespace clrt {
namespace {

constexpr const char* kVersion = "clrt 0.1.0";

// "640x480" -> width, height; CLI11 reports the returned message as a usage error.
std::string parse_resolution(const std::string& text, CliOptions& o) {
  static const std::regex form("([0-9]{1,6})[xX]([0-9]{1,6})");
  std::smatch m;
  if (!std::regex_match(text, m, form)) return "--resolution takes WIDTHxHEIGHT, e.g. 1280x720";
  o.width = std::stoi(m[1]);
  o.height = std::stoi(m[2]);
  if (*o.width < 1 || *o.height < 1) return "--resolution: width and height must be at least 1";
  return {};
}

}  // namespace

ParseResult parse_command_line(int argc, char** argv) {
  ParseResult result;
  CliOptions& o = result.options;
  CLI::App app{"clrt: a wavefront OpenCL ray tracer for .ray scenes", "clrt"};
  app.set_version_flag("--version", kVersion);
  app.add_option("scene", o.scene, "the .ray scene to render");
  app.add_option("-o,--outfile", o.outfile,
                 "output image; the extension picks the format: .png .ppm .fsf .pfm "
                 "(default: SCENE's name with .png)");
  app.add_option_function<std::string>(
      "--resolution", [&](const std::string& s) {
        const std::string error = parse_resolution(s, o);
        if (!error.empty()) throw CLI::ValidationError(error);
      },
      "image size WxH (overrides the scene's `resolution`)");
  app.add_option("--spp", o.samples, "camera samples per pixel (overrides `samples`)")
      ->check(CLI::Range(std::int64_t{1}, limits::kMaxSamples));
  app.add_option("--max-depth", o.max_depth, "deepest reflection/refraction bounce (overrides `maxdepth`)")
      ->check(CLI::Range(std::int64_t{0}, limits::kMaxDepth));
  app.add_option_function<std::string>(
         "--mode",
         [&](const std::string& mode) {
           o.mode = CLI::detail::to_lower(mode) == "cast" ? RenderMode::Cast : RenderMode::Trace;
         },
         "trace (shadows, reflection, refraction) or cast (local shading only)")
      ->check(CLI::IsMember({"trace", "cast"}, CLI::ignore_case));
  app.add_option("--device", o.device,
                 "cpu, gpu, all, P:D (platform:device index) or part of a device name")
      ->capture_default_str();
  app.add_flag("--list-devices", o.list_devices, "list the OpenCL devices and exit");
  app.add_option("--seed", o.seed, "seed of the random numbers (jitter, area lights)")
      ->capture_default_str();
  app.add_option("--wavefront", o.wavefront,
                 "rays in flight per queue: device memory grows with it "
                 "(default: 16384 on CPU devices, 1048576 on others)")
      ->check(CLI::Range(1u << 10, 1u << 26));
  std::string stats;
  app.add_option("--stats", stats, "print statistics to stdout: --stats or --stats=json")
      ->expected(0, 1)
      ->check(CLI::IsMember({"", "text", "json"}));
  app.add_flag("-q,--quiet", o.quiet, "print nothing but errors (no device line, no progress)");

  try {
    app.parse(argc, argv);
    if (app.count("--stats")) o.stats = stats == "json" ? StatsFormat::Json : StatsFormat::Text;
    if (o.scene.empty() && !o.list_devices) throw CLI::RequiredError("scene");
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    result.exit_code = code == 0 ? 0 : 2;
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
  r.seed = cli.seed;
  r.wavefront = cli.wavefront;
  return r;
}

std::string output_path(const CliOptions& cli) {
  if (!cli.outfile.empty()) return cli.outfile;
  return std::filesystem::path(cli.scene).stem().string() + ".png";
}

}  // namespace clrt
