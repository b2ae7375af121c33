// clrt-embree-compare SCENE.ray... [--rays N] [--threads T]: clrt's intersect and shadow
// kernels against Embree 3 on the same rays (README.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli/whole_number.hpp"
#include "compare_scene.hpp"
#include "cli/tool_command_line.hpp"
#include "device/device_context.hpp"
#include "device/device_select.hpp"
#include "render/renderer_program.hpp"
#include "report.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Compares clrt's intersection kernels with Embree 3 on the same rays.",
               "clrt-embree-compare"};
  clrt::identify_tool(app);
  std::vector<std::string> scenes;
  clrt::compare::CompareOptions options;
  std::string quality = "high", device_spec = "cpu";
  app.add_option("SCENE", scenes, ".ray scenes")->required();
  app.add_option("--rays", options.random_rays, "random (incoherent) rays per scene")
      ->transform(clrt::whole_number(1, 1 << 30))
      ->capture_default_str();
  app.add_option("--threads", options.threads, "Embree's host threads")
      ->transform(clrt::whole_number(1, 4096))
      ->capture_default_str();
  app.add_option("--runs", options.runs, "timed runs after a warm-up; the best counts")
      ->transform(clrt::whole_number(1, 1000))
      ->capture_default_str();
  app.add_option("--quality", quality, "Embree's BVH build quality")
      ->check(CLI::IsMember({"medium", "high"}))
      ->capture_default_str();
  bool robust = false;
  app.add_flag("--robust", robust, "RTC_SCENE_FLAG_ROBUST: watertight triangles, as clrt's");
  app.add_option("--device", device_spec, "clrt's OpenCL device (as clrt --device)")
      ->capture_default_str();
  if (const auto status = clrt::parse_tool_arguments(app, argc, argv)) return *status;
  options.quality = quality == "high" ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
  options.flags = robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
  try {
    clrt::DeviceContext device(clrt::select_devices(device_spec).front());
    std::fprintf(stderr, "clrt on %s; Embree %s, %d threads, build quality %s, scene flags %s\n",
                 device.name().c_str(), RTC_VERSION_STRING, options.threads, quality.c_str(),
                 robust ? "robust" : "none");
    const clrt::compute::program program = clrt::build_renderer_program(device, clrt::RenderMode::Trace, clrt::SceneFeatures{});
    std::vector<clrt::compare::SceneResult> results;
    for (const std::string& scene : scenes)
      results.push_back(clrt::compare::compare_scene(scene, device, program, options));
    clrt::compare::print_report(results);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clrt-embree-compare: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
