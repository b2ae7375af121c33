// clrt: render a .ray scene with the wavefront OpenCL renderer.
// Exit codes: 0 success, 1 runtime failure (device, kernel build, output), 2 usage or scene error.
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "cli/options.hpp"
#include "device/device_select.hpp"
#include "image/image.hpp"
#include "image/interrupt_cleanup.hpp"
#include "render/output_guard.hpp"
#include "render/render_limits.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Fails before the render, not after it, when the image could not be written anyway.
void check_output(const std::string& path) {
  clrt::format_from_path(path);
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw clrt::ImageError("cannot write " + path + ": " + dir.string() + " is not a directory");
}

int run(const clrt::CliOptions& cli) {
  const auto start = Clock::now();
  if (cli.list_devices) {
    std::cout << clrt::device_table(clrt::enumerate_devices());
    return 0;
  }
  clrt::RenderStats stats;
  clrt::Scene scene;
  try {
    scene = clrt::load_scene(cli.scene);
  } catch (const clrt::SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  stats.load_seconds = seconds_since(start);
  const std::string out = clrt::output_path(cli);
  try {
    check_output(out);
    clrt::check_output_is_not_input(out, scene);
  } catch (const clrt::ImageError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 2;
  }

  clrt::RenderSetup setup;
  setup.options = clrt::resolve_render_options(cli, scene);
  setup.devices = clrt::select_devices(cli.device);
  try {
    clrt::check_render_limits(scene, setup.options, clrt::measure_budget(setup.devices, setup.options));
  } catch (const clrt::RenderLimitError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return e.exit_code();
  }
  setup.profile = cli.stats != clrt::StatsFormat::None;
  setup.progress = !cli.quiet;
  if (!cli.quiet)
    for (const auto& d : setup.devices) std::cerr << "device " << clrt::describe_device(d) << "\n";

  const clrt::FloatImage image = clrt::render(scene, setup, stats);
  const auto write_start = Clock::now();
  clrt::write_image(out, image);
  stats.write_seconds = seconds_since(write_start);
  stats.total_seconds = seconds_since(start);
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  stats.peak_host_bytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
  if (cli.stats == clrt::StatsFormat::Text) std::cout << stats.to_text();
  if (cli.stats == clrt::StatsFormat::Json) std::cout << stats.to_json();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  clrt::remove_temporaries_on_signal();
  const clrt::ParseResult parsed = clrt::parse_command_line(argc, argv);
  if (parsed.exit_code) return *parsed.exit_code;
  try {
    return run(parsed.options);
  } catch (const std::exception& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 1;
  }
}
