// The turn that the rotations written after `endpose` add up to. A motion goes the shorter way
// between its two poses (docs/scene-format.md#motion), so a turn written as 180 degrees or more
// renders otherwise: `rotatey 200` as 160 degrees the other way, `rotatey 360` as no turn. The
// loader warns at the rotation that took the turn there rather than render it without a word.
#pragma once

#include <optional>
#include <string>

#include "math/vec3.hpp"
#include "scene/source_location.hpp"

namespace clrt {

class MotionTurn {
 public:
  // A rotation by `degrees` about `axis` (not zero), written at `where` after `endpose`.
  void add(double degrees, const Vec3& axis, const SourceLocation& where);

  // For an object placed now: the warning when the turn so far is one the motion cannot take as
  // written, once per rotation that made it so; else nothing.
  std::optional<std::string> take_warning();

 private:
  // The turn on the rotations' double cover (w, x, y, z): their written angles compose without
  // losing whether the total passed 180 degrees, as rotation matrices would.
  double w_ = 1, x_ = 0, y_ = 0, z_ = 0;
  // While every rotation shares one axis, the exact sum of their degrees about it (so that 600
  // degrees is not taken for -120).
  std::optional<Vec3> axis_;
  bool one_axis_ = true;
  double degrees_ = 0;
  std::optional<SourceLocation> past_at_;  // the rotation that took the turn to 180 degrees or more
  bool warned_ = false;
};

}  // namespace clrt
