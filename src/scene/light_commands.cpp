// light r g b KIND ...: ambient, point, directional, spot and area lights.
#include <algorithm>
#include <map>

#include "scene/command_table.hpp"
#include "scene/limits.hpp"
#include "scene/number.hpp"

namespace clrt {
namespace {

constexpr std::size_t kKind = 3;           // index of the kind word
constexpr std::size_t kFirst = kKind + 1;  // index of the kind's first argument

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

struct KindEntry {
  LightKind kind;
  void (*parse)(LightSpec&, const CommandArgs&);
};

const std::map<std::string, KindEntry>& light_kinds() {
  static const std::map<std::string, KindEntry> kinds = {
      {"ambient", {LightKind::Ambient, ambient}},
      {"point", {LightKind::Point, point}},
      {"directional", {LightKind::Directional, directional}},
      {"spot", {LightKind::Spot, spot}},
      {"area", {LightKind::Area, area}}};
  return kinds;
}

// The kind must be the fourth word. A number there means more than three colour numbers were
// written (as in the lecture's `light 0 6 0 6 0 6 point 3 3 3`, which lost its decimal points).
const KindEntry& find_kind(const CommandArgs& a) {
  if (a.count() == kKind)
    throw a.error_past_end(
        "wrong number of arguments: light needs a kind after r g b "
        "(ambient, point, directional, spot or area)");
  if (looks_numeric(a.word(kKind))) {
    std::size_t numbers = kKind;
    while (numbers < a.count() && looks_numeric(a.word(numbers))) ++numbers;
    throw a.error_at(kKind,
                     "wrong number of arguments: light takes 3 numbers (r g b) before its "
                     "kind, found " +
                         std::to_string(numbers));
  }
  const auto entry = light_kinds().find(lower_case(a.word(kKind).text));
  if (entry == light_kinds().end())
    throw a.error_at(kKind, "unknown light kind '" + excerpt(a.word(kKind).text) +
                                "' (expected ambient, point, directional, spot or area)");
  return entry->second;
}

void light(LoaderState& s, const CommandArgs& a) {
  for (std::size_t i = 0; i < std::min(a.count(), kKind); ++i) a.number(i);
  if (a.count() < kKind)
    throw a.error_past_end("wrong number of arguments: light needs r g b and a kind");
  LightSpec spec;
  spec.color = a.vec3(0);
  const KindEntry& kind = find_kind(a);
  spec.kind = kind.kind;
  kind.parse(spec, a);
  s.shadow_samples += shadow_samples(spec);
  if (s.shadow_samples > limits::kMaxShadowSamples)
    throw SceneError(a.command_location(),
                     "the lights so far take " + std::to_string(s.shadow_samples) +
                         " shadow-ray samples per shading point, more than the limit of " +
                         std::to_string(limits::kMaxShadowSamples));
  s.scene.lights.push_back(spec);
}

}  // namespace

void add_light_commands(CommandTable& table) { table["light"] = light; }

}  // namespace clrt
