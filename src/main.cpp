// clrt: render a .ray scene with the wavefront OpenCL renderer.
// Exit codes: 0 success, 1 runtime failure (device, kernel build, output), 2 usage or scene error.
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/options.hpp"
#include "device/device_select.hpp"
#include "image/image.hpp"
#include "render/renderer.hpp"
#include "render/usage_error.hpp"
#include "version.hpp"
#include "scene/scene.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Fails before the render, not after it, when the image could not be written anyway.
clrt::ImageOutput check_output(const clrt::CliOptions& cli) {
  const clrt::ImageOutput output = clrt::resolve_output(clrt::output_path(cli), cli.format);
  if (output.is_stdout()) return output;
  const std::string& path = output.path;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw clrt::ImageError("cannot write " + path + ": " + dir.string() + " is not a directory");
  return output;
}

int run(const clrt::CliOptions& cli) {
  const auto start = Clock::now();
  if (cli.list_devices) {
    std::cout << clrt::device_table(clrt::enumerate_devices());
    return 0;
  }
  clrt::RenderStats stats;
  stats.scene = cli.scene;
  stats.version = clrt_version_string();
  clrt::Scene scene;
  try {
    scene = clrt::load_scene(cli.scene);
  } catch (const clrt::SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  stats.load_seconds = seconds_since(start);
  clrt::ImageOutput out;
  try {
    out = check_output(cli);
  } catch (const clrt::ImageError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 2;
  }

  clrt::RenderSetup setup;
  setup.options = clrt::resolve_render_options(cli, scene);
  setup.devices = clrt::select_devices(cli.device);
  setup.profile = cli.stats != clrt::StatsFormat::None;
  setup.progress = !cli.quiet;
  clrt::check_render_setup(setup);
  if (!cli.quiet)
    for (const auto& d : setup.devices) std::cerr << "device " << clrt::describe_device(d) << "\n";

  const clrt::FloatImage image = clrt::render(scene, setup, stats);
  const auto write_start = Clock::now();
  clrt::write_image(out, image, {cli.exr_pixel});
  stats.write_seconds = seconds_since(write_start);
  stats.total_seconds = seconds_since(start);
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  stats.peak_host_bytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
  // Standard output may carry the image itself.
  std::ostream& stats_out = out.is_stdout() ? std::cerr : std::cout;
  if (cli.stats == clrt::StatsFormat::Text) stats_out << stats.to_text();
  if (cli.stats == clrt::StatsFormat::Json) stats_out << stats.to_json().dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const clrt::ParseResult parsed = clrt::parse_command_line(argc, argv);
  if (parsed.exit_code) return *parsed.exit_code;
  try {
    return run(parsed.options);
  } catch (const clrt::UsageError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 1;
  }
}
