// sphere, plane, cube, cylinder, cone, triangle, mesh: objects placed by the current transform.
#include <filesystem>

#include "scene/command_table.hpp"
#include "scene/coordinate_check.hpp"
#include "scene/limits.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/texture_images.hpp"
#include "shared/texture.h"

namespace clrt {
namespace {

void add_simple_shape(LoaderState& s, const CommandArgs& a, ShapeKind shape) {
  a.require_count({0});
  add_object(s, a.command_location(), shape);
}

void sphere(LoaderState& s, const CommandArgs& a) {
  a.require_count({0, 4});
  std::optional<Mat4> local;
  if (a.count() == 4) {
    const Vec3 centre = a.vec3(0);
    const double radius = a.number(3);
    if (radius <= 0) throw a.error_at(3, "the sphere radius must be > 0, found " + excerpt(a.word(3).text));
    local = Mat4::translate(centre) * Mat4::scale({radius, radius, radius});
  }
  add_object(s, a.command_location(), ShapeKind::Sphere, local);
}

void plane(LoaderState& s, const CommandArgs& a) { add_simple_shape(s, a, ShapeKind::Plane); }
void cube(LoaderState& s, const CommandArgs& a) { add_simple_shape(s, a, ShapeKind::Cube); }
void cylinder(LoaderState& s, const CommandArgs& a) { add_simple_shape(s, a, ShapeKind::Cylinder); }

void cone(LoaderState& s, const CommandArgs& a) {
  a.require_count({0, 2});
  double radii[2] = {1, 0};
  if (a.count() == 2) {
    for (std::size_t i = 0; i < 2; ++i) {
      radii[i] = a.number(i);
      if (radii[i] < 0) throw a.error_at(i, "a cone radius must be >= 0, found " + excerpt(a.word(i).text));
    }
    if (radii[0] == 0 && radii[1] == 0) throw a.error_at(0, "the cone radii must not both be 0");
  }
  InstanceSpec& instance = add_object(s, a.command_location(), ShapeKind::Cone);
  instance.cone_r0 = radii[0];
  instance.cone_r1 = radii[1];
}

// 9 numbers: the corners; 15: each corner followed by its (u, v).
void triangle(LoaderState& s, const CommandArgs& a) {
  a.require_count({9, 15});
  if (in_motion(s))
    throw SceneError(a.command_location(),
                     "a triangle cannot move: its corners are fixed in world space as it is read "
                     "(put moving triangles in an OBJ mesh, or `reset` before this one)");
  TriangleSpec t;
  const std::size_t stride = a.count() == 15 ? 5 : 3;
  for (std::size_t i = 0; i < a.count(); ++i) a.number(i);  // errors left to right
  t.v0 = s.transform.transform_point(a.vec3(0));
  t.v1 = s.transform.transform_point(a.vec3(stride));
  t.v2 = s.transform.transform_point(a.vec3(2 * stride));
  if (stride == 5) {
    t.has_uv = true;
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t j = 0; j < 2; ++j)
        t.uv[2 * k + j] = static_cast<float>(a.number_in(k * 5 + 3 + j, -limits::kMaxNumber,
                                                        limits::kMaxNumber, "a texture coordinate"));
  }
  for (const Vec3& v : {t.v0, t.v1, t.v2}) check_world_point(v, a.command_location());
  t.material = s.material;
  s.scene.triangles.push_back(t);
}

// What the scene so far leaves of the process's memory for a mesh.
MemoryLimit memory_left(const LoaderState& s) {
  const std::uint64_t used = loader_bytes(s);
  return {s.memory.bytes > used ? s.memory.bytes - used : 0, s.memory.source};
}

// A map_Kd or map_Ks as a texture of the scene: its index into Scene::textures.
int map_texture(LoaderState& s, const MtlTextureRef& map) {
  TextureSpec t;
  t.image = texture_image(s, map.path, map.where);
  t.clamp = map.clamp;
  t.scale[0] = map.scale.x;
  t.scale[1] = map.scale.y;
  t.offset[0] = map.offset.x;
  t.offset[1] = map.offset.y;
  s.scene.textures.push_back(t);
  return static_cast<int>(s.scene.textures.size()) - 1;
}

// The materials of the mesh's `usemtl` names join the scene's (whether or not an instance takes
// them: a mesh file is read once, and `mtl` may differ between its instances).
void add_mesh_materials(LoaderState& s, MeshData& mesh) {
  MeshMaterials found = load_mesh_materials(mesh, *s.files);
  for (std::size_t i = 0; i < found.by_name.size(); ++i) {
    std::optional<MaterialSpec>& m = found.by_name[i];
    if (m && found.color_maps[i]) m->textures[CLRT_TEXTURE_SLOT_COLOR] = map_texture(s, *found.color_maps[i]);
    if (m && found.specular_maps[i]) m->textures[CLRT_TEXTURE_SLOT_KS] = map_texture(s, *found.specular_maps[i]);
    if (m) s.scene.materials.push_back(*m);
    mesh.name_materials.push_back(m ? static_cast<int>(s.scene.materials.size()) - 1 : -1);
  }
  for (std::string& w : found.warnings) s.scene.warnings.push_back(std::move(w));
}

// The same resolved path is read once; every `mesh` naming it shares that MeshData.
int mesh_index(LoaderState& s, const CommandArgs& a) {
  const std::string path =
      (std::filesystem::path(s.scene_folder) / a.word(0).text).lexically_normal().generic_string();
  const auto known = s.mesh_by_path.find(path);
  if (known != s.mesh_by_path.end()) return known->second;
  try {
    s.scene.meshes.push_back(load_obj_mesh(path, *s.files, memory_left(s)));
    add_mesh_materials(s, s.scene.meshes.back());
  } catch (const MaterialLibraryError& e) {
    throw SceneError(a.command_location(), std::string("bad material library ") + e.what());
  } catch (const MeshError& e) {
    throw SceneError(a.command_location(), std::string("bad mesh file ") + e.what());
  }
  const int index = static_cast<int>(s.scene.meshes.size()) - 1;
  s.mesh_by_path[path] = index;
  return index;
}

void mesh(LoaderState& s, const CommandArgs& a) {
  if (a.count() > 1)
    throw a.error_at(1, "wrong number of arguments: mesh takes 1 path, found " +
                            std::to_string(a.count()) +
                            " (put a path with spaces in double quotes)");
  a.require_count({1});
  const int index = mesh_index(s, a);
  InstanceSpec& placed = add_object(s, a.command_location(), ShapeKind::Mesh);
  placed.mesh = index;
  placed.mesh_materials = s.mesh_materials;
}

}  // namespace

void add_object_commands(CommandTable& table) {
  table["sphere"] = sphere;
  table["plane"] = plane;
  table["cube"] = cube;
  table["cylinder"] = cylinder;
  table["cone"] = cone;
  table["triangle"] = triangle;
  table["mesh"] = mesh;
}

}  // namespace clrt
