// light r g b KIND ...: ambient, point, directional, spot and area lights.
#include <algorithm>

#include "scene/command_table.hpp"
#include "scene/light_kinds.hpp"
#include "scene/limits.hpp"
#include "scene/number.hpp"
#include "text/nearest_name.hpp"

namespace clrt {
namespace {

constexpr std::size_t kKind = kLightKindWord;

// The kind must be the fourth word. A number there means more than three colour numbers were
// written (as in the lecture's `light 0 6 0 6 0 6 point 3 3 3`, which lost its decimal points).
const LightKindEntry& find_kind(const CommandArgs& a) {
  if (a.count() == kKind)
    throw a.error_past_end("wrong number of arguments: light needs a kind after r g b (" +
                           light_kind_names() + ")");
  if (looks_numeric(a.word(kKind))) {
    std::size_t numbers = kKind;
    while (numbers < a.count() && looks_numeric(a.word(numbers))) ++numbers;
    throw a.error_at(kKind,
                     "wrong number of arguments: light takes 3 numbers (r g b) before its "
                     "kind, found " +
                         std::to_string(numbers));
  }
  const std::string kind = lower_case(a.word(kKind).text);
  const LightKindEntry* entry = find_light_kind(kind);
  if (!entry) {
    std::vector<std::string> names;
    for (const LightKindEntry& row : light_kind_table()) names.emplace_back(row.name);
    const std::string near = did_you_mean(kind, names);
    throw a.error_at(kKind, "unknown light kind '" + excerpt(a.word(kKind).text) + "' (" +
                                (near.empty() ? "" : near + " ") + "expected " +
                                light_kind_names() + ")");
  }
  return *entry;
}

void light(LoaderState& s, const CommandArgs& a) {
  for (std::size_t i = 0; i < std::min(a.count(), kKind); ++i) a.number(i);
  if (a.count() < kKind)
    throw a.error_past_end("wrong number of arguments: light needs r g b and a kind");
  LightSpec spec;
  spec.color = a.vec3(0);
  const LightKindEntry& kind = find_kind(a);
  spec.kind = kind.name;
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
