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

namespace {

// x_i = X + R r0_i and u_i = T + w x (R r0_i) for one particle: the one expression of each that
// the whole-array and the listed forms share, so both give the same bits.
struct Kinematics {
  Eigen::Matrix3d r;
  Vec3 c, t, w;
  explicit Kinematics(const BodyState& state)
      : r(rotation_matrix(state.orientation)),
        c(state.position),
        t(state.velocity),
        w(state.angular_velocity) {}
  void position(const Vec3Array& offset, std::size_t i, Vec3Array& out) const {
    const double ox = offset.x[i], oy = offset.y[i], oz = offset.z[i];
    out.x[i] = c.x() + r(0, 0) * ox + r(0, 1) * oy + r(0, 2) * oz;
    out.y[i] = c.y() + r(1, 0) * ox + r(1, 1) * oy + r(1, 2) * oz;
    out.z[i] = c.z() + r(2, 0) * ox + r(2, 1) * oy + r(2, 2) * oz;
  }
  void velocity(const Vec3Array& offset, std::size_t i, Vec3Array& out) const {
    const double ox = offset.x[i], oy = offset.y[i], oz = offset.z[i];
    const double ax = r(0, 0) * ox + r(0, 1) * oy + r(0, 2) * oz;  // R r0_i
    const double ay = r(1, 0) * ox + r(1, 1) * oy + r(1, 2) * oz;
    const double az = r(2, 0) * ox + r(2, 1) * oy + r(2, 2) * oz;
    out.x[i] = t.x() + w.y() * az - w.z() * ay;
    out.y[i] = t.y() + w.z() * ax - w.x() * az;
    out.z[i] = t.z() + w.x() * ay - w.y() * ax;
  }
};

}  // namespace

void particle_positions(const BodyState& state, const Vec3Array& offset, Vec3Array& position) {
  const std::size_t n = offset.size();
  position.resize(n);
  const Kinematics k(state);
  for (std::size_t i = 0; i < n; ++i) k.position(offset, i, position);
}

void particle_velocities(const BodyState& state, const Vec3Array& offset, Vec3Array& velocity) {
  const std::size_t n = offset.size();
  velocity.resize(n);
  const Kinematics k(state);
  for (std::size_t i = 0; i < n; ++i) k.velocity(offset, i, velocity);
}

void particle_kinematics_of(const BodyState& state, const Vec3Array& offset,
                            std::span<const std::int32_t> which, Vec3Array& position,
                            Vec3Array& velocity) {
  const Kinematics k(state);
  for (const std::int32_t i : which) {
    k.position(offset, static_cast<std::size_t>(i), position);
    k.velocity(offset, static_cast<std::size_t>(i), velocity);
  }
}

}  // namespace washout::rigid
