#include "scene/motion_turn.hpp"

#include <cmath>

#include "scene/limits.hpp"

namespace clrt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Axes this close in direction are one axis: rotatey and `rotate D 0 1 0` alike.
constexpr double kSameAxis = 1 - 1e-12;

}  // namespace

void MotionTurn::add(double degrees, const Vec3& axis, const SourceLocation& where) {
  const Vec3 n = normalize(axis);
  const double half = degrees * kPi / 360;
  const double s = std::sin(half), c = std::cos(half);
  const double rx = n.x * s, ry = n.y * s, rz = n.z * s;
  // This rotation after the turn so far: r * q.
  const double w = c * w_ - rx * x_ - ry * y_ - rz * z_;
  const double x = c * x_ + rx * w_ + ry * z_ - rz * y_;
  const double y = c * y_ - rx * z_ + ry * w_ + rz * x_;
  const double z = c * z_ + rx * y_ - ry * x_ + rz * w_;
  w_ = w, x_ = x, y_ = y, z_ = z;
  if (!axis_) {
    axis_ = n;
    degrees_ = degrees;
  } else if (one_axis_ && std::abs(dot(n, *axis_)) >= kSameAxis) {
    degrees_ += dot(n, *axis_) > 0 ? degrees : -degrees;
  } else {
    one_axis_ = false;
  }
  const bool too_far = one_axis_ ? std::abs(degrees_) >= 180 : w_ <= 0;
  if (!too_far) {
    past_at_.reset();
  } else if (!past_at_) {
    past_at_ = where;
    warned_ = false;
  }
}

std::optional<std::string> MotionTurn::take_warning() {
  if (!past_at_ || warned_) return std::nullopt;
  warned_ = true;
  std::string written, rendered;
  if (one_axis_) {
    written = short_number(degrees_) + " degrees";
    const double left = std::remainder(degrees_, 360);  // in [-180, 180]
    if (left == 0)
      rendered = "do not turn at all";
    else if (std::abs(left) == 180)
      rendered = "turn 180 degrees, either way round";
    else
      rendered = "turn " + short_number(std::abs(left)) + " degrees" +
                 ((left > 0) == (degrees_ > 0) ? "" : " the other way");
  } else {
    written = "a turn of 180 degrees or more";
    rendered = "turn " + short_number(360 * std::acos(std::min(1.0, -w_)) / kPi) + " degrees the other way";
  }
  return scene_warning(*past_at_, "the rotations after endpose come to " + written +
                                      ", but a motion takes the shorter way between its two poses: the "
                                      "objects that follow " +
                                      rendered);
}

}  // namespace clrt
