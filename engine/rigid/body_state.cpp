#include "engine/rigid/body_state.hpp"

namespace washout::rigid {

BodyState initial_state(const BodyModel& model) {
  BodyState state;
  state.position = model.centre_of_mass;
  return state;
}

Eigen::Matrix3d world_inertia(const BodyModel& model, const Eigen::Quaterniond& q) {
  if (model.dim == 2) {
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    inertia(2, 2) = model.inertia(2, 2);
    return inertia;
  }
  const Eigen::Matrix3d rotation = rotation_matrix(q);
  return rotation * model.inertia * rotation.transpose();
}

Eigen::Matrix3d world_inertia_inverse(const BodyModel& model, const Eigen::Quaterniond& q) {
  if (model.dim == 2) return model.inertia_inverse;  // already diag(0, 0, 1/I_zz)
  const Eigen::Matrix3d rotation = rotation_matrix(q);
  return rotation * model.inertia_inverse * rotation.transpose();
}

Vec3 angular_momentum(const BodyModel& model, const BodyState& state) {
  return world_inertia(model, state.orientation) * state.angular_velocity;
}

Vec3 linear_momentum(const BodyModel& model, const BodyState& state) {
  return model.mass * state.velocity;
}

double kinetic_energy(const BodyModel& model, const BodyState& state) {
  const Vec3 spin = angular_momentum(model, state);
  return 0.5 * model.mass * state.velocity.squaredNorm() + 0.5 * state.angular_velocity.dot(spin);
}

void particle_positions(const BodyState& state, const Vec3Array& offset, Vec3Array& position) {
  const std::size_t n = offset.size();
  position.resize(n);
  const Eigen::Matrix3d r = rotation_matrix(state.orientation);
  const Vec3 c = state.position;
  for (std::size_t i = 0; i < n; ++i) {
    const double ox = offset.x[i], oy = offset.y[i], oz = offset.z[i];
    position.x[i] = c.x() + r(0, 0) * ox + r(0, 1) * oy + r(0, 2) * oz;
    position.y[i] = c.y() + r(1, 0) * ox + r(1, 1) * oy + r(1, 2) * oz;
    position.z[i] = c.z() + r(2, 0) * ox + r(2, 1) * oy + r(2, 2) * oz;
  }
}

void particle_velocities(const BodyState& state, const Vec3Array& offset, Vec3Array& velocity) {
  const std::size_t n = offset.size();
  velocity.resize(n);
  const Eigen::Matrix3d r = rotation_matrix(state.orientation);
  const Vec3 t = state.velocity;
  const Vec3 w = state.angular_velocity;
  for (std::size_t i = 0; i < n; ++i) {
    const double ox = offset.x[i], oy = offset.y[i], oz = offset.z[i];
    const double ax = r(0, 0) * ox + r(0, 1) * oy + r(0, 2) * oz;  // R r0_i
    const double ay = r(1, 0) * ox + r(1, 1) * oy + r(1, 2) * oz;
    const double az = r(2, 0) * ox + r(2, 1) * oy + r(2, 2) * oz;
    velocity.x[i] = t.x() + w.y() * az - w.z() * ay;
    velocity.y[i] = t.y() + w.z() * ax - w.x() * az;
    velocity.z[i] = t.z() + w.x() * ay - w.y() * ax;
  }
}

}  // namespace washout::rigid
