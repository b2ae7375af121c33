// What a loader keeps while it reads a scene file top to bottom.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "math/mat4.hpp"
#include "scene/file_source.hpp"
#include "scene/memory_limit.hpp"
#include "scene/motion_turn.hpp"
#include "scene/scene.hpp"
#include "scene/source_location.hpp"

namespace clrt {

struct LoaderState {
  Scene scene;
  const FileSource* files = nullptr;        // where the scene's files are read from
  std::string scene_folder;                 // mesh paths are relative to it
  Mat4 transform;                           // the current transform M
  // The transform in force at `endpose`: objects are placed by it at time 0 and by `transform`
  // at time 1 (both the same: they do not move). `reset` clears it.
  std::optional<Mat4> start_pose;
  MotionTurn turn;  // the rotations written since `endpose`, for the warning of a long turn
  int material = 0;                         // the current material: index into scene.materials
  bool mesh_materials = true;               // `mtl on|off`
  std::map<std::string, int> mesh_by_path;  // resolved path -> index into scene.meshes
  std::int64_t shadow_samples = 0;          // shadow_samples() of the lights so far
  MemoryLimit memory = memory_limit();      // what the process may take, read as loading starts
  std::uint64_t text_bytes = 0;             // the scene file's text, held while it is read
  // The last command that set each camera vector, for errors found only after the whole file.
  std::optional<SourceLocation> eye_set_at, lookat_set_at, up_set_at;
};

// The scene's estimated memory (scene_memory.hpp) and its text.
std::uint64_t loader_bytes(const LoaderState& s);
// Throws SceneError at `where` when loader_bytes exceed `s.memory`; the loaders call it every
// kMemoryCheckCommands commands and after a mesh.
void check_loader_memory(const LoaderState& s, const SourceLocation& where);
constexpr std::size_t kMemoryCheckCommands = 1024;

// Appends an instance of `shape` placed by `to_world` with the current material; a SceneError at
// `where` when the transform or its inverse is not finite.
InstanceSpec& add_instance(LoaderState& s, const SourceLocation& where, ShapeKind shape,
                           const Mat4& to_world);

// Whether an `endpose` is in force with transforms after it: objects placed now move.
bool in_motion(const LoaderState& s);

// Appends a `.ray` object placed by the current transform times `local` (its own placement, such
// as a sphere's centre and radius). After `endpose` it moves, from the pose `endpose` recorded
// (times `local`) at time 0 to the current one at time 1, unless the two are the same. A
// SceneError at `where` when a pose cannot be inverted or the two differ in handedness.
InstanceSpec& add_object(LoaderState& s, const SourceLocation& where, ShapeKind shape,
                         const std::optional<Mat4>& local = std::nullopt);

}  // namespace clrt
