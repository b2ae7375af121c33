// Every light kind once: the word that names it in `light r g b KIND ...` and its syntax, how its
// arguments are read, how many shadow-ray samples it takes at a shading point, whether it has a
// place in the world, how path mode reads it, and the device record it becomes. The loader, the
// messages, the limits, the coordinate check, the dark-scene note, the device's light table
// (src/render/frame_setup.cpp) and the syntax list of docs/scene-format.md (checked by
// tests/scene/light_test.cpp) read this table; a new kind is a row here (and its value in
// LightKind, its parameters in LightSpec), its row in CLRT_LIGHT_KINDS (kernels/shared/scene.h)
// and its device file in kernels/render/lights/.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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
  LightKind kind;
  const char* name;
  const char* syntax;  // its arguments after the kind word, as docs/scene-format.md writes them
  void (*parse)(LightSpec& light, const CommandArgs& args);
  std::int64_t (*shadow_samples)(const LightSpec& light);
  bool placed;  // its position lies in the world (the coordinate check bounds it)
  PathReading path_reading;
  // Fills the device record's kind and the fields the kind reads (kernels/render/lights/); null
  // for a kind with no record (ambient light, summed into RenderParams.ambient).
  void (*to_device)(const LightSpec& light, dev::Light& record);
};

const std::vector<LightKindEntry>& light_kind_table();
const LightKindEntry& light_kind(LightKind kind);
// The entry named `name` (lower case), or null.
const LightKindEntry* find_light_kind(const std::string& name);
// "ambient, point, directional, spot or area", for messages.
std::string light_kind_names();

}  // namespace clrt
