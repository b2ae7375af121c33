// The emitter table: the glowing surfaces that path mode's glow light samples
// (kernels/render/lights/glow.h). A glowing sphere placed by a similarity (rotation, uniform
// scale, translation, as instance_bounds.hpp's world_sphere finds) is a row; every triangle of a
// glowing mesh, cube (two per face) or loose `triangle` is a row, in world space. The other
// glowing shapes (planes, which are unbounded, cylinders, cones and spheres stretched into
// ellipsoids) are left out: paths that hit them still see their glow, with nothing to share it
// with.
#pragma once

#include <vector>

#include "geometry/geometry_data.hpp"
#include "geometry/mesh_table.hpp"
#include "scene/scene.hpp"

namespace clrt {

// The Rec. 709 luminance the device's glow_luminance computes, by which rows share the samples.
double glow_luminance(const Vec3& radiance);

// Whether `scene` glows on a surface of a kind the table holds, before its geometry is built: then
// path mode has a glow light (unless all those surfaces are degenerate triangles, which give no
// row).
bool glow_is_sampled(const Scene& scene);

// Fills out.emitters and out.emitter_power from the instances already in `out` (with their
// instance_source) and the triangle sources they use, and marks each glowing instance's
// Instance.glow.
void build_emitter_table(const Scene& scene, const std::vector<TriangleSource>& sources,
                         GeometryData& out);

}  // namespace clrt
