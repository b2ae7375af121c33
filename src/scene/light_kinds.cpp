#include "scene/light_kinds.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "math/stratification_grid.hpp"
#include "scene/device_vector.hpp"
#include "scene/limits.hpp"
#include "scene/number.hpp"
#include "scene/scene_json.hpp"

namespace clrt {
namespace {

using Json = nlohmann::ordered_json;

constexpr std::size_t kFirst = kLightFirstArgument;

void ambient(LightSpec&, const CommandArgs& a) { a.require_count({0}, kFirst, "light"); }

void point(LightSpec& light, const CommandArgs& a) {
  a.require_count({3}, kFirst, "light");
  light.position = a.vec3(kFirst);
}

void directional(LightSpec& light, const CommandArgs& a) {
  a.require_count({3}, kFirst, "light");
  light.direction = a.nonzero_vec3(kFirst, "the light direction");
}

// spot x y z dx dy dz angle [exp]
void spot(LightSpec& light, const CommandArgs& a) {
  a.require_count({7, 8}, kFirst, "light");
  light.position = a.vec3(kFirst);
  light.direction = a.nonzero_vec3(kFirst + 3, "the spot axis");
  const std::size_t angle = kFirst + 6, exponent = kFirst + 7;
  light.angle_degrees = a.number(angle);
  if (light.angle_degrees <= 0 || light.angle_degrees > 180)
    throw a.error_at(angle,
                     "the spot angle must be > 0 and <= 180 degrees, found " + excerpt(a.word(angle).text));
  if (a.count() > exponent) {
    light.exponent = a.number(exponent);
    if (light.exponent < 0)
      throw a.error_at(exponent, "the spot exponent must be >= 0, found " + excerpt(a.word(exponent).text));
  }
}

// The device samples an area light and weighs its samples by the cross product of its edges (its
// normal, as long as its area), in single precision: that product must neither vanish, overflow
// nor underflow there when squared, and the edges must be far enough from parallel for its
// direction to be known. Otherwise path mode's samples of the light were NaN.
void check_area_edges(const CommandArgs& a, const Vec3& u, const Vec3& v) {
  const float ux = static_cast<float>(u.x), uy = static_cast<float>(u.y), uz = static_cast<float>(u.z);
  const float vx = static_cast<float>(v.x), vy = static_cast<float>(v.y), vz = static_cast<float>(v.z);
  const float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const float n2 = nx * nx + ny * ny + nz * nz;
  const double sine = length(cross(u, v)) / (length(u) * length(v));
  if (n2 >= std::numeric_limits<float>::min() && n2 <= std::numeric_limits<float>::max() &&
      sine >= limits::kMinAreaLightEdgeSine)
    return;
  throw a.error_at(kFirst + 3,
                   sine >= limits::kMinAreaLightEdgeSine
                       ? "the area light's edges span an area of " + short_number(length(cross(u, v))) +
                             ", too small or too large for the device's single precision"
                       : "the area light's edges u and v are parallel (the sine of the angle "
                         "between them must be at least " +
                             short_number(limits::kMinAreaLightEdgeSine) + ")");
}

// area x y z ux uy uz vx vy vz [samples]
void area(LightSpec& light, const CommandArgs& a) {
  a.require_count({9, 10}, kFirst, "light");
  light.position = a.vec3(kFirst);
  light.edge_u = a.nonzero_vec3(kFirst + 3, "the area light's edge u");
  light.edge_v = a.nonzero_vec3(kFirst + 6, "the area light's edge v");
  check_area_edges(a, light.edge_u, light.edge_v);
  const std::size_t samples = kFirst + 9;
  light.samples = a.count() > samples
                      ? a.whole_number(samples, 1, static_cast<int>(limits::kMaxLightSamples),
                                       "the number of light samples")
                      : 16;
}

std::int64_t no_samples(const LightSpec&) { return 0; }
std::int64_t one_sample(const LightSpec&) { return 1; }
std::int64_t its_samples(const LightSpec& light) { return light.samples; }

void point_record(const LightSpec&, dev::Light& d) { d.kind = dev::CLRT_LIGHT_POINT; }

void directional_record(const LightSpec& light, dev::Light& d) {
  d.kind = dev::CLRT_LIGHT_DIRECTIONAL;
  d.direction = f4_of(normalize(light.direction));
}

void spot_record(const LightSpec& light, dev::Light& d) {
  d.kind = dev::CLRT_LIGHT_SPOT;
  d.direction = f4_of(normalize(light.direction));
  d.cos_cutoff = static_cast<float>(std::cos(light.angle_degrees * M_PI / 180.0));
  d.spot_exponent = static_cast<float>(light.exponent);
}

// Besides its edges, what path mode's solid-angle sampling needs of the light at every sample
// (kernels/render/lights/area.h), worked out once in double: the edges' lengths, the unit
// normal, and whether the edges are perpendicular within 1e-5 of their lengths' product.
void area_record(const LightSpec& light, dev::Light& d) {
  d.kind = dev::CLRT_LIGHT_AREA;
  d.edge_u = f4_of(light.edge_u);
  d.edge_v = f4_of(light.edge_v);
  const double lu = length(light.edge_u), lv = length(light.edge_v);
  d.edge_u.w = static_cast<float>(lu);
  d.edge_v.w = static_cast<float>(lv);
  d.direction = f4_of(normalize(cross(light.edge_u, light.edge_v)));
  d.direction.w = std::fabs(dot(light.edge_u, light.edge_v)) <= 1e-5 * lu * lv ? 1.0f : 0.0f;
  const Grid grid = stratification_grid(d.samples);
  d.grid_u = grid.u;
  d.grid_v = grid.v;
}

void nothing_to_dump(const LightSpec&, Json&) {}

void point_dump(const LightSpec& light, Json& j) { j["position"] = json_of(light.position); }

void directional_dump(const LightSpec& light, Json& j) { j["direction"] = json_of(light.direction); }

void spot_dump(const LightSpec& light, Json& j) {
  j["position"] = json_of(light.position);
  j["direction"] = json_of(light.direction);
  j["angle_degrees"] = light.angle_degrees;
  j["exponent"] = light.exponent;
}

void area_dump(const LightSpec& light, Json& j) {
  j["corner"] = json_of(light.position);
  j["edge_u"] = json_of(light.edge_u);
  j["edge_v"] = json_of(light.edge_v);
  j["samples"] = light.samples;
}

}  // namespace

const std::vector<LightKindEntry>& light_kind_table() {
  using P = PathReading;
  static const std::vector<LightKindEntry> table = {
      {"ambient", "", ambient, no_samples, false, P::Unused, nullptr, nothing_to_dump},
      {"point", "x y z", point, one_sample, true, P::FallsOff, point_record, point_dump},
      {"directional", "dx dy dz", directional, one_sample, false, P::LikeWhitted,
       directional_record, directional_dump},
      {"spot", "x y z dx dy dz angle [exp]", spot, one_sample, true, P::FallsOff, spot_record,
       spot_dump},
      {"area", "x y z ux uy uz vx vy vz [samples]", area, its_samples, true, P::LikeWhitted,
       area_record, area_dump}};
  return table;
}

const LightKindEntry& light_kind(const std::string& name) {
  if (const LightKindEntry* entry = find_light_kind(name)) return *entry;
  throw std::logic_error("no light kind '" + name + "' in light_kind_table()");
}

const LightKindEntry* find_light_kind(const std::string& name) {
  for (const LightKindEntry& entry : light_kind_table())
    if (name == entry.name) return &entry;
  return nullptr;
}

std::string light_kind_names() {
  const std::vector<LightKindEntry>& table = light_kind_table();
  std::string out;
  for (std::size_t i = 0; i < table.size(); ++i)
    out += (i == 0 ? "" : i + 1 == table.size() ? " or " : ", ") + std::string(table[i].name);
  return out;
}

}  // namespace clrt
