// load_mesh_materials (scene/mesh_loader.hpp): a mesh's `usemtl` names resolved through its
// `mtllib` libraries.
#include <filesystem>
#include <set>
#include <sstream>

#include "image/input_file_checks.hpp"
#include "scene/limits.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/mtl_material.hpp"
#include "scene/mtl_reader.hpp"

namespace clrt {
namespace {

// An MTL file is a page of text; anything near this size is no material library.
constexpr std::uint64_t kMaxLibraryBytes = std::uint64_t{64} << 20;

// The files an `mtllib` line may name: the whole line (a name with spaces), then each of its
// words, as the format has it.
std::vector<std::string> library_candidates(const MeshName& line, const std::filesystem::path& folder) {
  std::vector<std::string> names{line.name};
  std::istringstream words(line.name);
  for (std::string word; words >> word;)
    if (word != line.name) names.push_back(word);
  for (std::string& name : names) name = (folder / name).lexically_normal().generic_string();
  return names;
}

// The libraries an `mtllib` line names that can be read, with a warning for those that cannot.
std::vector<std::pair<std::string, std::unique_ptr<FileBytes>>> open_libraries(const MeshName& line,
                                                                              const std::filesystem::path& folder,
                                                                              const FileSource& files,
                                                                              std::vector<std::string>& warnings) {
  std::vector<std::pair<std::string, std::unique_ptr<FileBytes>>> opened;
  const std::vector<std::string> candidates = library_candidates(line, folder);
  std::string first_failure;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    try {
      opened.emplace_back(candidates[i], files.open(candidates[i], kMaxLibraryBytes));
      if (i == 0) break;  // the whole line names a file
    } catch (const std::exception& e) {
      if (i == 0) {
        first_failure = e.what();
        continue;
      }
      warnings.push_back(scene_warning(line.where, "material library '" + candidates[i] + "' cannot be read (" +
                                                    e.what() + "); its materials are left out"));
    }
  }
  if (candidates.size() == 1 && opened.empty())
    warnings.push_back(scene_warning(line.where, "material library '" + candidates[0] + "' cannot be read (" +
                                                  first_failure + "); its materials are left out"));
  return opened;
}

}  // namespace

MeshMaterials load_mesh_materials(const MeshData& mesh, const FileSource& files) {
  MeshMaterials out;
  if (mesh.material_names.empty()) return out;
  const std::filesystem::path folder = std::filesystem::path(mesh.path).parent_path();
  std::vector<MtlLibrary> libraries;
  std::vector<std::filesystem::path> library_folders;  // each library's, for its maps' paths
  std::set<std::string> read;
  for (const MeshName& line : mesh.libraries)
    for (auto& [path, file] : open_libraries(line, folder, files, out.warnings)) {
      if (!read.insert(path).second) continue;
      try {
        libraries.push_back(parse_mtl(without_byte_order_mark(file->text()), path));
        library_folders.push_back(std::filesystem::path(path).parent_path());
      } catch (const SceneError& e) {
        throw MaterialLibraryError(e.where(), e.message());
      }
      out.warnings.insert(out.warnings.end(), libraries.back().warnings.begin(), libraries.back().warnings.end());
    }
  for (const MeshName& name : mesh.material_names) {
    // Later libraries' definitions win, as later definitions within one library do.
    const MtlMaterial* found = nullptr;
    std::size_t holder = libraries.size();
    while (holder > 0 && !found) found = libraries[--holder].find(name.name);
    const auto resolved = [&](const std::optional<MtlTextureRef>& map) {
      std::optional<MtlTextureRef> out_map = map;
      if (out_map) out_map->path = (library_folders[holder] / map->path).lexically_normal().generic_string();
      return out_map;
    };
    out.color_maps.push_back(found ? resolved(found->map_kd) : std::nullopt);
    out.specular_maps.push_back(found ? resolved(found->map_ks) : std::nullopt);
    if (found) {
      out.by_name.push_back(material_from_mtl(*found, out.warnings));
      continue;
    }
    out.by_name.push_back(std::nullopt);
    out.warnings.push_back(scene_warning(name.where, "material '" + name.name +
                                                      "' is in no material library; its faces take the scene's "
                                                      "current material"));
  }
  return out;
}

}  // namespace clrt
