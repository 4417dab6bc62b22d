#include "engine/rigid/quaternion_integrator.hpp"

#include <cmath>

namespace washout::rigid {

Eigen::Quaterniond quaternion_from_rotation_vector(const Vec3& phi) {
  const double angle2 = phi.squaredNorm();
  const double angle = std::sqrt(angle2);
  // sin(a/2)/a, by its Taylor series where the quotient would lose digits.
  const double sinc_half = angle < 1e-4 ? 0.5 - angle2 / 48.0 : std::sin(0.5 * angle) / angle;
  Eigen::Quaterniond q(std::cos(0.5 * angle), sinc_half * phi.x(), sinc_half * phi.y(),
                       sinc_half * phi.z());
  return q.normalized();
}

// Quaternion update, METHOD.md Rigid bodies:
//   q^{n+1} = normalise(q^n + dt/2 (0, w^{n+1}) * q^n)   or the exact rotation-vector update
//   q^{n+1} = exp(dt/2 (0, w^{n+1})) * q^n.
Eigen::Quaterniond advance_orientation(const Eigen::Quaterniond& q, const Vec3& w, double dt,
                                       QuaternionUpdate update) {
  if (update == QuaternionUpdate::kExactRotationVector) {
    return (quaternion_from_rotation_vector(dt * w) * q).normalized();
  }
  const Eigen::Quaterniond spin(0.0, w.x(), w.y(), w.z());
  Eigen::Quaterniond rate = spin * q;
  Eigen::Quaterniond next(q.w() + 0.5 * dt * rate.w(), q.x() + 0.5 * dt * rate.x(),
                          q.y() + 0.5 * dt * rate.y(), q.z() + 0.5 * dt * rate.z());
  return next.normalized();
}

}  // namespace washout::rigid
