// The loaders behind load_scene(), one per scene format, and what they share.
#pragma once

#include <string>

#include "scene/file_source.hpp"
#include "scene/scene.hpp"

namespace clrt {

// The whole file; a SceneError at 1:1 when it cannot be read (missing, a folder, a read error).
std::string read_scene_file(const FileSource& files, const std::string& path);

Scene load_ray_scene(const std::string& path, const FileSource& files);
Scene load_nff_scene(const std::string& path, const FileSource& files);

}  // namespace clrt
