#include <filesystem>

#include "scene/command_args.hpp"
#include "scene/scene_loaders.hpp"

namespace clrt {
namespace {

struct ForeignFormat {
  const char* extension;
  const char* what;
};

// Files other renderers read, which a user may hand clrt by mistake: named by their extension, so
// that they get a word on what they are rather than an unknown command on their first line.
constexpr ForeignFormat kForeignFormats[] = {
    {".pbrt", "a pbrt scene"},        {".xml", "a Mitsuba scene (or other XML)"},
    {".gltf", "a glTF scene"},        {".glb", "a glTF scene"},
    {".pov", "a POV-Ray scene"},      {".blend", "a Blender file"},
    {".usd", "a USD scene"},          {".usda", "a USD scene"},
    {".usdc", "a USD scene"},         {".fbx", "an FBX scene"},
    {".obj", "an OBJ mesh"},          {".ply", "a PLY mesh"},
    {".stl", "an STL mesh"}};

void refuse_foreign_format(const std::string& path) {
  const std::string extension = lower_case(std::filesystem::path(path).extension().string());
  for (const ForeignFormat& format : kForeignFormats) {
    if (extension != format.extension) continue;
    const bool mesh = extension == ".obj";
    throw SceneError(
        SourceLocation::whole_file(path),
        std::string("this is ") + format.what + ", not a scene clrt reads: clrt reads .ray scenes " +
            "(docs/scene-format.md) and NFF (.nff)" +
            (mesh ? "; place the mesh in a .ray scene with `mesh \"" +
                        std::filesystem::path(path).filename().string() + "\"`"
                  : ""));
  }
}

}  // namespace

Scene load_scene(const std::string& path, const FileSource& files) {
  refuse_foreign_format(path);
  if (lower_case(std::filesystem::path(path).extension().string()) == ".nff")
    return load_nff_scene(path, files);
  return load_ray_scene(path, files);
}

}  // namespace clrt
