// What a loader keeps while it reads a scene file top to bottom.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "math/mat4.hpp"
#include "scene/file_source.hpp"
#include "scene/memory_limit.hpp"
#include "scene/scene.hpp"
#include "scene/source_location.hpp"

namespace clrt {

struct LoaderState {
  Scene scene;
  const FileSource* files = nullptr;        // where the scene's files are read from
  std::string scene_folder;                 // mesh paths are relative to it
  Mat4 transform;                           // the current transform M
  int material = 0;                         // the current material: index into scene.materials
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

}  // namespace clrt
