#include "engine/rigid/newton_euler.hpp"

#include "engine/rigid/free_rotation.hpp"

namespace washout::rigid {
namespace {

// Newton-Euler update, METHOD.md Rigid bodies (translation):
//   T^{n+1} = T^n + dt (g + (F_f + F_c)/M),   X^{n+1} = X^n + dt T^{n+1}
void advance_translation(const BodyModel& model, BodyState& state, const Vec3& force,
                         const Vec3& gravity, double dt) {
  Vec3 acceleration = gravity + force / model.mass;
  if (model.dim == 2) acceleration.z() = 0.0;
  state.velocity += dt * acceleration;
  state.position += dt * state.velocity;
}

// 2D: rotation about z only; no gyroscopic term. w_z += dt M_z / I_zz, then q turns about z.
void advance_rotation_2d(const BodyModel& model, BodyState& state, const Vec3& torque, double dt,
                         const IntegratorOptions& options) {
  const double wz = state.angular_velocity.z() + dt * torque.z() * model.inertia_inverse(2, 2);
  state.angular_velocity = Vec3(0.0, 0.0, wz);
  state.orientation =
      advance_orientation(state.orientation, state.angular_velocity, dt, options.quaternion);
}

// Newton-Euler update, METHOD.md Rigid bodies (rotation, as written):
//   w^{n+1} = w^n + dt I^-1 (M_f + M_c - w^n x I w^n),  I = R I_body R^T,
//   q^{n+1} = normalise(q^n + dt/2 (0, w^{n+1}) * q^n)  (or the exact rotation-vector update)
void advance_rotation_explicit_euler(const BodyModel& model, BodyState& state, const Vec3& torque,
                                     double dt, const IntegratorOptions& options) {
  const Eigen::Matrix3d inertia = world_inertia(model, state.orientation);
  const Eigen::Matrix3d inverse = world_inertia_inverse(model, state.orientation);
  const Vec3 w = state.angular_velocity;
  const Vec3 gyroscopic = w.cross(inertia * w);
  state.angular_velocity = w + dt * inverse * (torque - gyroscopic);
  state.orientation =
      advance_orientation(state.orientation, state.angular_velocity, dt, options.quaternion);
}

// The same kick written for L = I w (I dw/dt + w x I w = M is dL/dt = M in the world frame),
// followed by the exact-per-axis torque-free rotation; see free_rotation.hpp.
void advance_rotation_momentum_splitting(const BodyModel& model, BodyState& state,
                                         const Vec3& torque, double dt) {
  const Vec3 momentum = angular_momentum(model, state) + dt * torque;
  state.orientation = free_rotation(model, state.orientation, momentum, dt);
  state.angular_velocity = world_inertia_inverse(model, state.orientation) * momentum;
}

}  // namespace

void advance_body(const BodyModel& model, BodyState& state, const BodyLoad& load,
                  const Vec3& gravity, double t, double dt, const IntegratorOptions& options) {
  switch (model.motion) {
    case MotionKind::kFixed:
      state.velocity.setZero();
      state.angular_velocity.setZero();
      return;
    case MotionKind::kPrescribed:
      state = model.prescribed(t + dt);
      state.orientation.normalize();
      return;
    case MotionKind::kDynamic:
      break;
  }
  advance_translation(model, state, load.force, gravity, dt);
  if (model.dim == 2) {
    advance_rotation_2d(model, state, load.torque, dt, options);
  } else if (options.rotation == RotationScheme::kExplicitEuler) {
    advance_rotation_explicit_euler(model, state, load.torque, dt, options);
  } else {
    advance_rotation_momentum_splitting(model, state, load.torque, dt);
  }
}

}  // namespace washout::rigid
