// The loaders behind load_scene(), one per scene format, and what they share.
#pragma once

#include <string>

#include "scene/file_source.hpp"
#include "scene/scene.hpp"

namespace clrt {

// The whole file; a SceneError for the file as a whole when it cannot be read (missing, a
// folder, a read error) or is no text (an image given as the scene).
std::string read_scene_file(const FileSource& files, const std::string& path);

Scene load_ray_scene(const std::string& path, const FileSource& files);
Scene load_nff_scene(const std::string& path, const FileSource& files);

}  // namespace clrt
