#include "engine/rigid/rotation_angle.hpp"

#include <cmath>
#include <numbers>

namespace washout::rigid {
namespace {

double wrap(double angle) {
  constexpr double pi = std::numbers::pi;
  angle = std::remainder(angle, 2.0 * pi);  // [-pi, pi]
  return angle == -pi ? pi : angle;
}

}  // namespace

double twist_angle(const Eigen::Quaterniond& q, const Vec3& axis) {
  return wrap(2.0 * std::atan2(q.vec().dot(axis), q.w()));
}

double RotationAngleTracker::update(const Eigen::Quaterniond& q) {
  const double twist = twist_angle(q, axis_);
  angle_ += wrap(twist - last_twist_);
  last_twist_ = twist;
  return angle_;
}

}  // namespace washout::rigid
