#include <cmath>
#include <string>

#include "scene/loader_state.hpp"

namespace clrt {
namespace {

bool all_finite(const Mat4& m) {
  for (const auto& row : m.m)
    for (double v : row)
      if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

InstanceSpec place_instance(ShapeKind shape, const Mat4& to_world, int material) {
  InstanceSpec instance;
  instance.shape = shape;
  instance.material = material;
  instance.transform = to_world;
  return instance;
}

int mesh_face_material(const MeshData& mesh, std::size_t t) {
  const std::uint32_t name = mesh.triangle_names.empty() ? kNoMeshMaterial : mesh.triangle_names.at(t);
  return name == kNoMeshMaterial ? -1 : mesh.name_materials.at(name);
}

int mesh_triangle_material(const InstanceSpec& instance, const MeshData& mesh, std::size_t t) {
  const int own = instance.mesh_materials ? mesh_face_material(mesh, t) : -1;
  return own >= 0 ? own : instance.material;
}

SourceLocation instance_location(const Scene& scene, const InstanceSpec& instance) {
  return {scene.path, instance.place.line, instance.place.column};
}

namespace {

// Extreme scale factors can overflow the product or make it numerically singular.
void check_invertible(const Mat4& m, const SourceLocation& where, const char* which) {
  if (!all_finite(m) || !all_finite(m.inverse()))
    throw SceneError(where, std::string("the transform that places this object") + which +
                                " cannot be inverted (a scale factor too large or too small)");
}

bool same(const Mat4& a, const Mat4& b) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (a.m[r][c] != b.m[r][c]) return false;
  return true;
}

}  // namespace

InstanceSpec& add_instance(LoaderState& s, const SourceLocation& where, ShapeKind shape,
                           const Mat4& to_world) {
  InstanceSpec instance = place_instance(shape, to_world, s.material);
  instance.place = {where.line, where.column};
  check_invertible(instance.transform, where, "");
  s.scene.instances.push_back(instance);
  return s.scene.instances.back();
}

bool in_motion(const LoaderState& s) { return s.start_pose && !same(*s.start_pose, s.transform); }

InstanceSpec& add_object(LoaderState& s, const SourceLocation& where, ShapeKind shape,
                         const std::optional<Mat4>& local) {
  // Without a placement of its own the pose is taken as it is, bit for bit (a product with the
  // identity could turn a -0 into a +0).
  const auto placed = [&](const Mat4& pose) { return local ? pose * *local : pose; };
  if (s.start_pose)
    if (std::optional<std::string> warning = s.turn.take_warning()) s.scene.warnings.push_back(std::move(*warning));
  if (!in_motion(s)) return add_instance(s, where, shape, placed(s.transform));
  const Mat4 end = placed(s.transform);
  check_invertible(end, where, " when the shutter closes");
  InstanceSpec& instance = add_instance(s, where, shape, placed(*s.start_pose));
  // A pose cannot turn into its mirror image by rotating and stretching: the stretch would pass
  // through flat.
  if ((instance.transform.determinant() < 0) != (end.determinant() < 0)) {
    s.scene.instances.pop_back();
    throw SceneError(where,
                     "this object's two poses differ in handedness (one of them is mirrored by a "
                     "negative scale factor), so no motion can take one to the other");
  }
  instance.motion = static_cast<int>(s.scene.end_transforms.size());
  s.scene.end_transforms.push_back(end);
  return instance;
}

}  // namespace clrt
