// environment FILE [SCALE]: the image of the radiance arriving from every direction.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <variant>

#include "image/image.hpp"
#include "scene/command_table.hpp"
#include "scene/limits.hpp"
#include "scene/scene_image.hpp"
#include "scene/scene_memory.hpp"
#include "scene/texture_images.hpp"

namespace clrt {
namespace {

// The linear part of `m` as a rotation (orthonormal columns, determinant 1) within 1e-6; the map
// turns with it, and a scale or shear would have no meaning for directions.
bool is_rotation(const Mat4& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(dot(m.column(i), m.column(j)) - (i == j ? 1.0 : 0.0)) > 1e-6) return false;
  return m.determinant() > 0;
}

void environment(LoaderState& s, const CommandArgs& a) {
  a.require_count({1, 2});
  EnvironmentSpec env;
  env.path = (std::filesystem::path(s.scene_folder) / a.word(0).text).lexically_normal().generic_string();
  if (a.count() > 1) env.scale = a.number_in(1, 0, limits::kMaxNumber, "the environment's scale");
  if (in_motion(s))
    throw a.error_at(0, "the environment cannot move: it turns with the current transform, which "
                        "differs from the one `endpose` recorded; put `environment` before "
                        "`endpose` or after `reset`");
  if (!is_rotation(s.transform))
    throw a.error_at(0, "the environment turns with the current transform, whose linear part must "
                        "be a rotation (no scale or shear); put `environment` before them or after "
                        "`reset`");
  env.rotation = s.transform;
  // As a texture's: the header decides what is allocated, so it is checked first. While the map
  // decodes, the file, the decoded pixels (4 bytes each for 8-bit images, 12 for floats) and, for
  // 8-bit ones, their linear values are held together.
  const std::uint64_t used = loader_bytes(s);
  const auto check_header = [&](const ImageInfo& info, std::uint64_t file_bytes) {
    check_image_side(info, "an environment");
    const auto pixels = static_cast<std::uint64_t>(info.width) * static_cast<std::uint64_t>(info.height);
    const std::uint64_t decoding = file_bytes + pixels * (holds_floats(info.format) ? 12 : 4 + 12);
    const std::uint64_t held =
        environment_host_bytes(info.width, info.height) + environment_table_bytes(info.width, info.height);
    check_image_memory(used + std::max(decoding, held), s.memory);
  };
  AnyImage image;
  try {
    image = read_scene_image(*s.files, env.path, s.memory.bytes, check_header);
  } catch (const std::exception& e) {
    throw a.error_at(0, "cannot read the environment image " + excerpt(env.path) + ": " + e.what());
  }
  if (const auto* bytes = std::get_if<Rgba8Image>(&image)) {
    env.width = bytes->width;
    env.height = bytes->height;
    const std::vector<std::uint8_t>& rgba = bytes->frames.at(0);
    env.rgb.resize(rgba.size() / 4 * 3);
    for (std::size_t i = 0; i < env.rgb.size(); ++i) env.rgb[i] = srgb_to_linear(rgba[i + i / 3]);
  } else {
    FloatImage& floats = std::get<FloatImage>(image);
    env.width = floats.width;
    env.height = floats.height;
    env.rgb = std::move(floats.rgb);
  }
  for (std::size_t i = 0; i < env.rgb.size(); ++i) {
    const float v = env.rgb[i];
    if (!(v >= 0 && v <= limits::kMaxNumber)) {
      const std::size_t pixel = i / 3;
      throw a.error_at(0, "the environment image " + excerpt(env.path) + " has the radiance " +
                              short_number(v) + " at pixel (" + std::to_string(pixel % env.width) + ", " +
                              std::to_string(pixel / env.width) + "): each channel must be in [0, " +
                              short_number(limits::kMaxNumber) + "]");
    }
  }
  s.scene.environment = std::move(env);
}

}  // namespace

void add_environment_command(CommandTable& table) { table["environment"] = environment; }

}  // namespace clrt
