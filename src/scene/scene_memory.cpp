#include "scene/scene_memory.hpp"
#include "scene/texture_images.hpp"

namespace clrt {
namespace {

constexpr std::uint64_t kGeometryBytesPerPrimitive = 256;

template <class Table>
std::uint64_t table_bytes(const Table& table) {
  return table.size() * sizeof(typename Table::value_type);
}

}  // namespace

std::uint64_t environment_table_bytes(std::int64_t width, std::int64_t height) {
  const auto w = static_cast<std::uint64_t>(width), h = static_cast<std::uint64_t>(height);
  return 16 * (w * h + (h + 3) / 4);
}

std::uint64_t environment_host_bytes(std::int64_t width, std::int64_t height) {
  const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  return 12 * pixels + 2 * environment_table_bytes(width, height);
}

std::uint64_t estimated_geometry_bytes(const Scene& scene) {
  std::uint64_t primitives = scene.instances.size() + scene.triangles.size() + 1;
  for (const MeshData& mesh : scene.meshes) primitives += mesh.corners.size() / 3;
  const std::uint64_t environment =
      scene.environment ? environment_table_bytes(scene.environment->width, scene.environment->height) : 0;
  return primitives * kGeometryBytesPerPrimitive + environment;
}

std::uint64_t estimated_scene_bytes(const Scene& scene) {
  std::uint64_t growing = table_bytes(scene.triangles);
  for (const MeshData& mesh : scene.meshes)
    growing += table_bytes(mesh.positions) + table_bytes(mesh.normals) + table_bytes(mesh.corners) +
               table_bytes(mesh.corner_normals) + table_bytes(mesh.texcoords) + table_bytes(mesh.corner_texcoords) +
               table_bytes(mesh.triangle_names);
  const std::uint64_t environment =
      scene.environment ? environment_host_bytes(scene.environment->width, scene.environment->height) : 0;
  std::uint64_t textures = 0;
  for (const TextureImage& image : scene.texture_images) textures += texture_image_bytes(image);
  return 2 * growing + table_bytes(scene.instances) + table_bytes(scene.end_transforms) + environment +
         textures + estimated_geometry_bytes(scene);
}

void check_scene_memory(std::uint64_t needed, const MemoryLimit& limit, const SourceLocation& where) {
  if (needed <= limit.bytes) return;
  throw SceneError(where, "loading stopped here: the scene needs " + mebibytes(needed) +
                              " so far, " + mebibytes(limit.bytes) + " available (" +
                              limit.source + ")");
}

}  // namespace clrt
