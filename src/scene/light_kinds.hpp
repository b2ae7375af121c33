// Every light kind once: the word that names it in `light r g b KIND ...` and its syntax, how its
// arguments are read, how many shadow-ray samples it takes at a shading point, whether it has a
// place in the world, how path mode reads it, the device record it becomes and what the scene
// dump writes of it. The loader, the messages, the limits, the coordinate check, the dark-scene
// note, the device's light table (src/render/frame_setup.cpp), the scene dump and the syntax list
// of docs/scene-format.md (checked by tests/scene/light_test.cpp) read this table. A new kind is a
// row here and its device file in kernels/render/lights/, which the build adds to the device's
// list of kinds (CLRT_LIGHT_KINDS, kernels/shared/scene.h) by itself.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene/command_args.hpp"
#include "scene/scene.hpp"
#include "shared/scene.h"

namespace clrt {

// Index of the kind word in a light command's arguments, and of the kind's first argument.
constexpr std::size_t kLightKindWord = 3;
constexpr std::size_t kLightFirstArgument = kLightKindWord + 1;

// How path mode reads a kind, against the Whitted modes (docs/path-tracing.md#units).
enum class PathReading {
  Unused,         // not in path mode (ambient light)
  FallsOff,       // its intensity falls off as 1/d^2, so a Whitted scene may turn out dark
  LikeWhitted,    // it lights a surface as brightly as in the Whitted modes
};

struct LightKindEntry {
  const char* name;  // as the command writes it, and LightSpec::kind holds it
  const char* syntax;  // its arguments after the kind word, as docs/scene-format.md writes them
  void (*parse)(LightSpec& light, const CommandArgs& args);
  std::int64_t (*shadow_samples)(const LightSpec& light);
  bool placed;  // its position lies in the world (the coordinate check bounds it)
  PathReading path_reading;
  // Fills the device record's kind and the fields the kind reads (kernels/render/lights/); null
  // for a kind with no record (ambient light, summed into RenderParams.ambient).
  void (*to_device)(const LightSpec& light, dev::Light& record);
  // Adds the parameters it read to `out`, its object in the scene dump (docs/scene-json.md).
  void (*dump)(const LightSpec& light, nlohmann::ordered_json& out);
};

const std::vector<LightKindEntry>& light_kind_table();
// The row named `name`, which must be one (LightSpec::kind).
const LightKindEntry& light_kind(const std::string& name);
// The entry named `name` (lower case), or null.
const LightKindEntry* find_light_kind(const std::string& name);
// "ambient, point, directional, spot or area", for messages.
std::string light_kind_names();

}  // namespace clrt
