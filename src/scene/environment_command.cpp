// environment FILE [SCALE]: the image of the radiance arriving from every direction.
#include <cmath>
#include <filesystem>
#include <variant>

#include "image/image.hpp"
#include "scene/command_table.hpp"
#include "scene/limits.hpp"

namespace clrt {
namespace {

// PNG and PPM hold sRGB-encoded 8-bit values; the renderer wants radiance.
float srgb_decode(std::uint8_t byte) {
  const double c = byte / 255.0;
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

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
  if (!is_rotation(s.transform))
    throw a.error_at(0, "the environment turns with the current transform, whose linear part must "
                        "be a rotation (no scale or shear); put `environment` before them or after "
                        "`reset`");
  env.rotation = s.transform;
  AnyImage image;
  try {
    image = read_any_image(env.path);
  } catch (const std::exception& e) {
    throw a.error_at(0, "cannot read the environment image " + excerpt(env.path) + ": " + e.what());
  }
  if (const auto* bytes = std::get_if<Rgba8Image>(&image)) {
    env.width = bytes->width;
    env.height = bytes->height;
    const std::vector<std::uint8_t>& rgba = bytes->frames.at(0);
    env.rgb.resize(rgba.size() / 4 * 3);
    for (std::size_t i = 0; i < env.rgb.size(); ++i) env.rgb[i] = srgb_decode(rgba[i + i / 3]);
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
