#include "render_support.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "cl_fixture.hpp"
#include "device/device_select.hpp"
#include "render/render_stats.hpp"
#include "render/renderer.hpp"

namespace clrt::test {

std::string test_scene(const std::string& name) {
  return std::string(CLRT_SOURCE_DIR) + "/tests/render/scenes/" + name;
}

std::vector<std::string> repository_scenes() {
  std::vector<std::string> out;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(std::string(CLRT_SOURCE_DIR) + "/scenes"))
    if (entry.path().extension() == ".ray") out.push_back(entry.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

FloatImage render_file(const std::string& path, const std::function<void(RenderOptions&)>& adjust,
                       const std::string& device_spec) {
  const Scene scene = load_scene(path);
  RenderSetup setup;
  setup.options = RenderOptions::from_scene(scene);
  if (adjust) adjust(setup.options);
  setup.devices = select_devices(device_spec.empty() ? test_device_spec() : device_spec);
  RenderStats stats;
  return render(scene, setup, stats);
}

bool same_bits(const FloatImage& a, const FloatImage& b) {
  return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
         std::memcmp(a.rgb.data(), b.rgb.data(), sizeof(float) * a.rgb.size()) == 0;
}

std::array<int, 3> pixel_rgb(const Rgba8Image& image, int i, int j) {
  const auto at = 4 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(image.width) +
                       static_cast<std::size_t>(i));
  const auto& f = image.frames.at(0);
  return {f[at], f[at + 1], f[at + 2]};
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

CommandResult run_clrt(const std::string& arguments, const std::string& environment) {
  return run_program(CLRT_EXE, arguments, environment);
}

CommandResult run_program(const std::string& program, const std::string& arguments,
                          const std::string& environment) {
  const std::string command = (environment.empty() ? "" : "env " + environment + " ") + "'" +
                              program + "' " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  CommandResult result;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace clrt::test
