// How an MTL material becomes one of clrt's (docs/scene-format.md#materials-from-mtl).
#pragma once

#include <string>
#include <vector>

#include "scene/mtl_reader.hpp"
#include "scene/scene.hpp"

namespace clrt {

// The clrt material of an MTL one, starting from the default material and taking what the MTL
// says: C = Kd with kd 1, ks the largest channel of Ks (0 for illum 0 and 1), n = Ns, kr = ks for
// the illumination models with mirror reflection (3 to 8), kt = 1 - d, ior = Ni and emission = Ke.
// What it cannot render (a coloured highlight, texture maps) is added to `warnings`, once per
// material.
MaterialSpec material_from_mtl(const MtlMaterial& mtl, std::vector<std::string>& warnings);

}  // namespace clrt
