#pragma once
// The rotation angle of a body about a chosen axis, for 2D-like motion (a girder turning in the
// vertical plane of the flow; every 2D body, about z). It is the twist of the swing-twist
// decomposition of q: exact for rotations about the axis, and continuous over many turns.
#include <Eigen/Geometry>

#include "engine/core/vec3.hpp"

namespace washout::rigid {

// 2 atan2(q_v . a, q_w) wrapped to (-pi, pi]: the angle of q about the unit axis a.
double twist_angle(const Eigen::Quaterniond& q, const Vec3& axis);

// Follows the angle through whole turns: each update adds the change since the last one,
// wrapped to (-pi, pi] (a body turns less than half a turn per step).
class RotationAngleTracker {
 public:
  explicit RotationAngleTracker(const Vec3& axis = Vec3::UnitZ()) : axis_(axis.normalized()) {}
  double update(const Eigen::Quaterniond& q);
  double angle() const { return angle_; }
  double last_twist() const { return last_twist_; }
  // Continues a tracker saved with angle() and last_twist() (a restarted run).
  void restore(double angle, double last_twist) {
    angle_ = angle;
    last_twist_ = last_twist;
  }
  const Vec3& axis() const { return axis_; }

 private:
  Vec3 axis_;
  double angle_ = 0.0, last_twist_ = 0.0;
};

}  // namespace washout::rigid
