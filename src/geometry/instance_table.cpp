#include "geometry/instance_table.hpp"

#include <stdexcept>

namespace clrt {
namespace {

dev::f4 row(const Mat4& m, int r, bool with_translation) {
  return {static_cast<float>(m.m[r][0]), static_cast<float>(m.m[r][1]),
          static_cast<float>(m.m[r][2]), with_translation ? static_cast<float>(m.m[r][3]) : 0.0f};
}

dev::u32 device_shape(ShapeKind shape) {
  switch (shape) {
    case ShapeKind::Sphere: return CLRT_SHAPE_SPHERE;
    case ShapeKind::Plane: return CLRT_SHAPE_PLANE;
    case ShapeKind::Cube: return CLRT_SHAPE_CUBE;
    case ShapeKind::Cylinder: return CLRT_SHAPE_CYLINDER;
    case ShapeKind::Cone: return CLRT_SHAPE_CONE;
    case ShapeKind::Mesh: return CLRT_SHAPE_MESH;
  }
  throw std::logic_error("unknown shape kind");
}

// Normals go to world space by (M^-1)^T, which the device takes from the same rows.
dev::Instance placed(const Mat4& inverse) {
  dev::Instance inst{};
  inst.glow = CLRT_NO_GLOW;  // until the emitter table says otherwise
  inst.motion = CLRT_NO_MOTION;  // until the geometry's motion table says otherwise
  for (int r = 0; r < 3; ++r) inst.world_to_object[r] = row(inverse, r, true);
  return inst;
}

}  // namespace

dev::Instance device_instance(const InstanceSpec& spec, dev::u32 mesh, dev::u32 material_rows) {
  dev::Instance inst = placed(spec.transform.inverse());
  inst.shape = device_shape(spec.shape);
  inst.material = static_cast<dev::u32>(spec.material);
  inst.mesh = spec.shape == ShapeKind::Mesh ? mesh : 0;
  inst.material_rows =
      spec.shape == ShapeKind::Mesh && spec.mesh_materials ? material_rows : CLRT_NO_MATERIAL_ROWS;
  inst.cone_r0 = static_cast<float>(spec.cone_r0);
  inst.cone_r1 = static_cast<float>(spec.cone_r1);
  return inst;
}

dev::Instance loose_triangle_instance(dev::u32 mesh, dev::u32 material_rows) {
  dev::Instance inst = placed(Mat4::identity());
  inst.shape = CLRT_SHAPE_MESH;
  inst.material = 0;  // every row is a triangle's own
  inst.mesh = mesh;
  inst.material_rows = material_rows;
  return inst;
}

}  // namespace clrt
