// Scene instances as the device's Instance records.
#pragma once

#include "math/mat4.hpp"
#include "scene/scene.hpp"
#include "shared/scene.h"

namespace clrt {

// The record of a canonical shape or mesh instance; `mesh` is the device mesh index and
// `material_rows` where that mesh's rows of triangle materials start (CLRT_NO_MATERIAL_ROWS when
// it has none), both used only for ShapeKind::Mesh.
dev::Instance device_instance(const InstanceSpec& spec, dev::u32 mesh, dev::u32 material_rows);

// The identity-placed instance of the mesh that holds the scene's loose triangles, whose
// materials come per triangle from the rows at `material_rows`.
dev::Instance loose_triangle_instance(dev::u32 mesh, dev::u32 material_rows);

}  // namespace clrt
