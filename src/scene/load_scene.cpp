#include <filesystem>

#include "scene/command_args.hpp"
#include "scene/scene_loaders.hpp"

namespace clrt {

Scene load_scene(const std::string& path, const FileSource& files) {
  if (lower_case(std::filesystem::path(path).extension().string()) == ".nff")
    return load_nff_scene(path, files);
  return load_ray_scene(path, files);
}

}  // namespace clrt
