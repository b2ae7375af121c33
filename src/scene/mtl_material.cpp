#include "scene/mtl_material.hpp"

#include <algorithm>

namespace clrt {
namespace {

double largest(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

// The models whose surfaces reflect as a mirror: 3 (ray-traced reflection) to 8.
bool mirrors(int illum) { return illum >= 3 && illum <= 8; }

}  // namespace

MaterialSpec material_from_mtl(const MtlMaterial& mtl, std::vector<std::string>& warnings) {
  MaterialSpec m;  // clrt's default material
  if (mtl.kd) {
    m.color = *mtl.kd;
    m.kd = 1;
  }
  const int illum = mtl.illum.value_or(2);
  const double specular = mtl.ks ? std::min(1.0, largest(*mtl.ks)) : 0.0;
  if (illum >= 2) m.ks = specular;
  if (mtl.ks && illum >= 2 && (mtl.ks->x != mtl.ks->y || mtl.ks->y != mtl.ks->z))
    warnings.push_back(scene_warning(mtl.where, "material '" + mtl.name +
                                                 "': clrt's highlight is white; Ks gives its strength only"));
  if (mtl.ns) m.shininess = *mtl.ns;
  if (mirrors(illum)) m.kr = specular;
  if (mtl.dissolve) m.kt = 1.0 - *mtl.dissolve;
  if (mtl.ni) m.ior = *mtl.ni;
  if (mtl.ke) m.emission = *mtl.ke;
  if (mtl.map_bump)
    warnings.push_back(scene_warning(mtl.map_bump->where, "material '" + mtl.name + "': bump map '" +
                                                           mtl.map_bump->path + "' is not rendered (clrt has no bump maps)"));
  return m;
}

}  // namespace clrt
