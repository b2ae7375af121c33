#include "scene/scene.hpp"

namespace clrt {

InstanceSpec place_instance(ShapeKind shape, const Mat4& to_world, int material) {
  InstanceSpec instance;
  instance.shape = shape;
  instance.material = material;
  instance.transform = to_world;
  instance.inverse = to_world.inverse();
  instance.normal_matrix = instance.inverse.transposed();
  return instance;
}

}  // namespace clrt
