#include "scene/light_kinds.hpp"

#include <stdexcept>

#include "scene/limits.hpp"
#include "scene/number.hpp"

namespace clrt {
namespace {

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

// area x y z ux uy uz vx vy vz [samples]
void area(LightSpec& light, const CommandArgs& a) {
  a.require_count({9, 10}, kFirst, "light");
  light.position = a.vec3(kFirst);
  light.edge_u = a.nonzero_vec3(kFirst + 3, "the area light's edge u");
  light.edge_v = a.nonzero_vec3(kFirst + 6, "the area light's edge v");
  const std::size_t samples = kFirst + 9;
  light.samples = a.count() > samples
                      ? a.whole_number(samples, 1, static_cast<int>(limits::kMaxLightSamples),
                                       "the number of light samples")
                      : 16;
}

std::int64_t no_samples(const LightSpec&) { return 0; }
std::int64_t one_sample(const LightSpec&) { return 1; }
std::int64_t its_samples(const LightSpec& light) { return light.samples; }

}  // namespace

const std::vector<LightKindEntry>& light_kind_table() {
  static const std::vector<LightKindEntry> table = {
      {LightKind::Ambient, "ambient", ambient, no_samples, false},
      {LightKind::Point, "point", point, one_sample, true},
      {LightKind::Directional, "directional", directional, one_sample, false},
      {LightKind::Spot, "spot", spot, one_sample, true},
      {LightKind::Area, "area", area, its_samples, true}};
  return table;
}

const LightKindEntry& light_kind(LightKind kind) {
  for (const LightKindEntry& entry : light_kind_table())
    if (entry.kind == kind) return entry;
  throw std::logic_error("a light kind missing from light_kind_table()");
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
