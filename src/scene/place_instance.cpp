#include <cmath>

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

SourceLocation instance_location(const Scene& scene, const InstanceSpec& instance) {
  return {scene.path, instance.place.line, instance.place.column};
}

InstanceSpec& add_instance(LoaderState& s, const SourceLocation& where, ShapeKind shape,
                           const Mat4& to_world) {
  InstanceSpec instance = place_instance(shape, to_world, s.material);
  instance.place = {where.line, where.column};
  // Extreme scale factors can overflow the product or make it numerically singular.
  if (!all_finite(instance.transform) || !all_finite(instance.transform.inverse()))
    throw SceneError(where,
                     "the transform that places this object cannot be inverted (a scale factor "
                     "too large or too small)");
  s.scene.instances.push_back(instance);
  return s.scene.instances.back();
}

}  // namespace clrt
