// What the end-to-end tests share: the test scenes, renders through clrt::render(), and runs of
// the clrt executable.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "render/render_options.hpp"
#include "scene/scene.hpp"

namespace clrt::test {

// tests/render/scenes/NAME
std::string test_scene(const std::string& name);

// Every .ray file under the repository's scenes/, sorted.
std::vector<std::string> repository_scenes();

// Loads and renders `path` on the test device (CLRT_TEST_DEVICE, else the first CPU device) or
// the devices `device_spec` names, with the scene's own settings changed by `adjust`.
FloatImage render_file(const std::string& path,
                       const std::function<void(RenderOptions&)>& adjust = {},
                       const std::string& device_spec = "");

// Whether two images have the same size and the same bits in every channel.
bool same_bits(const FloatImage& a, const FloatImage& b);

// Pixel (i, j) of the first frame, rgb.
std::array<int, 3> pixel_rgb(const Rgba8Image& image, int i, int j);

// `path` in single quotes, as run_clrt's arguments need it.
std::string quoted(const std::string& path);

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs the clrt executable with `arguments` (already quoted where needed), with `environment`
// (e.g. "POCL_MAX_PTHREAD_COUNT=1") added to the inherited environment.
CommandResult run_clrt(const std::string& arguments, const std::string& environment = "");
// The same for any program.
CommandResult run_program(const std::string& program, const std::string& arguments,
                          const std::string& environment = "");

// The whole file, or an empty string when it does not exist.
std::string file_bytes(const std::string& path);

}  // namespace clrt::test
