// reset, translate, scale, rotate, rotatex/y/z: each new transform X makes current = X * current.
// endpose: the current transform becomes the pose at time 0 of the objects that follow, and the
// transforms after it give their pose at time 1.
#include <string>

#include "scene/command_table.hpp"

namespace clrt {
namespace {

void reset(LoaderState& s, const CommandArgs& a) {
  a.require_count({0});
  s.transform = Mat4::identity();
  s.start_pose.reset();
  s.turn = MotionTurn();
}

void endpose(LoaderState& s, const CommandArgs& a) {
  a.require_count({0});
  s.start_pose = s.transform;
  s.turn = MotionTurn();
}

// The rotations after `endpose` are followed, since a motion cannot turn 180 degrees or more.
void turn(LoaderState& s, const CommandArgs& a, double degrees, const Vec3& axis) {
  s.transform = Mat4::rotate(degrees, axis) * s.transform;
  if (s.start_pose) s.turn.add(degrees, axis, a.command_location());
}

void translate(LoaderState& s, const CommandArgs& a) {
  a.require_count({3});
  s.transform = Mat4::translate(a.vec3(0)) * s.transform;
}

void scale(LoaderState& s, const CommandArgs& a) {
  a.require_count({3});
  const Vec3 factors = a.vec3(0);
  for (int i = 0; i < 3; ++i)
    if (factors[i] == 0)
      throw a.error_at(static_cast<std::size_t>(i), "a scale factor must not be 0");
  s.transform = Mat4::scale(factors) * s.transform;
}

void rotate(LoaderState& s, const CommandArgs& a) {
  a.require_count({4});
  const double degrees = a.number(0);
  turn(s, a, degrees, a.nonzero_vec3(1, "the rotation axis"));
}

template <int Axis>
void rotate_about_principal_axis(LoaderState& s, const CommandArgs& a) {
  a.require_count({1});
  const Vec3 axis{Axis == 0 ? 1.0 : 0.0, Axis == 1 ? 1.0 : 0.0, Axis == 2 ? 1.0 : 0.0};
  turn(s, a, a.number(0), axis);
}

}  // namespace

void add_transform_commands(CommandTable& table) {
  table["reset"] = reset;
  table["endpose"] = endpose;
  table["translate"] = translate;
  table["scale"] = scale;
  table["rotate"] = rotate;
  table["rotatex"] = rotate_about_principal_axis<0>;
  table["rotatey"] = rotate_about_principal_axis<1>;
  table["rotatez"] = rotate_about_principal_axis<2>;
}

}  // namespace clrt
