// s and c: spheres, and cones or cylinders between two points, placed as clrt's canonical shapes.
#include <algorithm>
#include <cmath>

#include "scene/nff_state.hpp"

namespace clrt {
namespace {

// s x y z radius. A negative radius (NFF: "only the inside is visible") is read as its size:
// clrt's surfaces have both sides. A sphere of radius 0 cannot be seen and is left out.
void sphere(NffState& s, const CommandArgs& a) {
  a.require_count({4});
  const Vec3 centre = a.vec3(0);
  const double r = std::abs(a.number(3));
  if (r == 0) return;
  add_instance(s.loader, a.command_location(), ShapeKind::Sphere,
               Mat4::translate(centre) * Mat4::scale({r, r, r}));
}

// The rotation that turns +y onto the direction of `axis` (any non-zero length).
Mat4 rotation_from_y(const Vec3& axis) {
  const Vec3 turn = cross({0, 1, 0}, axis);
  const double sine = length(turn), cosine = axis.y;  // both times |axis|
  if (sine == 0) return cosine > 0 ? Mat4::identity() : Mat4::rotate(180, {1, 0, 0});
  return Mat4::rotate(std::atan2(sine, cosine) * 180.0 / M_PI, turn);
}

// c base.x base.y base.z base_radius apex.x apex.y apex.z apex_radius. clrt's cylinder and cone
// run from y = -1 to 1 with radius 1 at most, so the canonical shape is scaled by R = the larger
// radius across and half the axis length along y, turned onto the axis and moved to its middle;
// a cone keeps the ratio of each radius to R (r0 at the base, r1 at the apex). Negative radii read
// as their sizes, as for spheres; both radii 0 is a line, left out.
void cone_or_cylinder(NffState& s, const CommandArgs& a) {
  a.require_count({8});
  for (std::size_t i = 0; i < a.count(); ++i) a.number(i);  // errors left to right
  const Vec3 base = a.vec3(0), apex = a.vec3(4);
  const double base_r = std::abs(a.number(3)), apex_r = std::abs(a.number(7));
  const Vec3 axis = apex - base;
  if (axis == Vec3{0, 0, 0})
    throw a.error_at(4,
                     "the apex is the base point: a cone or cylinder needs an axis of "
                     "non-zero length");
  const double r = std::max(base_r, apex_r);
  if (r == 0) return;
  // Scaled, then turned, then moved: multiplied in the order a .ray file's transforms are.
  const Mat4 to_world = Mat4::translate((base + apex) * 0.5) *
                        (rotation_from_y(axis) * Mat4::scale({r, length(axis) / 2, r}));
  const bool cylinder = base_r == apex_r;
  InstanceSpec& instance = add_instance(s.loader, a.command_location(),
                                        cylinder ? ShapeKind::Cylinder : ShapeKind::Cone, to_world);
  if (cylinder) return;
  instance.cone_r0 = base_r / r;
  instance.cone_r1 = apex_r / r;
}

}  // namespace

void add_nff_shape_entities(NffTable& table) {
  table["s"] = sphere;
  table["c"] = cone_or_cylinder;
}

}  // namespace clrt
