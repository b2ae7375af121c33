// Every light kind once: the word that names it in `light r g b KIND ...`, how its arguments are
// read, how many shadow-ray samples it takes at a shading point, and whether it has a place in
// the world. The loader, the limits and the coordinate check read this table; a new kind is a
// row here, its parameters in LightSpec (scene.hpp), and its device side (frame_setup.cpp's
// make_lights, kernels/render/lights.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/command_args.hpp"
#include "scene/scene.hpp"

namespace clrt {

// Index of the kind word in a light command's arguments, and of the kind's first argument.
constexpr std::size_t kLightKindWord = 3;
constexpr std::size_t kLightFirstArgument = kLightKindWord + 1;

struct LightKindEntry {
  LightKind kind;
  const char* name;
  void (*parse)(LightSpec& light, const CommandArgs& args);
  std::int64_t (*shadow_samples)(const LightSpec& light);
  bool placed;  // its position lies in the world (the coordinate check bounds it)
};

const std::vector<LightKindEntry>& light_kind_table();
const LightKindEntry& light_kind(LightKind kind);
// The entry named `name` (lower case), or null.
const LightKindEntry* find_light_kind(const std::string& name);
// "ambient, point, directional, spot or area", for messages.
std::string light_kind_names();

}  // namespace clrt
