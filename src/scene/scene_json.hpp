// The scene as clrt read it, as JSON (docs/scene-json.md): what the converters to other
// renderers (tools/mitsuba, tools/bench/path_race) read instead of parsing scene files again.
#pragma once

#include <functional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "scene/scene.hpp"

namespace clrt {

// The "version" of the document; it changes whenever a reader of the last one would misread it.
// 2 since textures: a reader of 1 would take a textured material for its plain colour.
constexpr int kSceneJsonVersion = 2;

// Writes `scene` as one JSON document, in pieces to `write`: an element of the objects', the
// meshes' and the triangles' tables is converted only when it is written, so a scene of
// millions of spheres dumps in little more memory than it loads in.
void write_scene_json(const Scene& scene, const std::function<void(const std::string&)>& write);

// A point or vector as the document writes it: [x, y, z].
nlohmann::ordered_json json_of(const Vec3& v);

}  // namespace clrt
