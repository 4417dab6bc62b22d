// Newton-Euler stepping: free fall against X0 + T0 t + g t^2/2, 2D rotation under a constant
// torque, fixed and prescribed bodies, and the quaternion staying unit length.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/rigid/body_state.hpp"
#include "engine/rigid/lattice_body.hpp"
#include "engine/rigid/newton_euler.hpp"

namespace washout::rigid {
namespace {

BodyModel box_model(int dim) {
  return make_body_model(lattice_box(dim, 0.02, Vec3::Zero(), Vec3(0.3, 0.2, 0.1), 800.0));
}

// METHOD.md updates T first, then X with the new T (semi-implicit Euler), so after n steps
//   X_n = X0 + T0 t + g t^2/2 + g t dt/2   and   T_n = T0 + g t   exactly.
// The test checks that the error against the analytic free fall is this known first-order term
// (to 1e-9 of it: rounding only) and that it halves with dt; T is exact to rounding.
TEST(RigidNewtonEuler, FreeFallMatchesTheAnalyticParabola3D) {
  const BodyModel model = box_model(3);
  const Vec3 g(0, 0, -9.81), x0(0.1, 0.2, 3.0), t0(1.0, -0.5, 2.0);
  double previous_error = 0.0;
  for (double dt : {1e-3, 5e-4}) {
    BodyState s = initial_state(model);
    s.position = x0;
    s.velocity = t0;
    s.angular_velocity = Vec3(1.0, 2.0, -3.0);  // spinning must not disturb the centre of mass
    const int steps = static_cast<int>(std::lround(1.0 / dt));
    for (int n = 0; n < steps; ++n) advance_body(model, s, {}, g, n * dt, dt);
    const double t = steps * dt;
    const Vec3 exact = x0 + t0 * t + 0.5 * g * t * t;
    const double error = (s.position - exact).norm();
    const double predicted = 0.5 * g.norm() * t * dt;
    std::printf(
        "free fall 3D, dt = %.1e, t = 1 s: |X - X_exact| = %.3e m (predicted g t dt/2 = "
        "%.3e), |T - T_exact| = %.1e m/s\n",
        dt, error, predicted, (s.velocity - (t0 + g * t)).norm());
    EXPECT_NEAR(error, predicted, 1e-9 * predicted + 1e-12);
    EXPECT_LT((s.velocity - (t0 + g * t)).norm(), 1e-11);
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 2.0, 1e-6);
    }
    previous_error = error;
  }
}

TEST(RigidNewtonEuler, FreeFall2DStaysInThePlane) {
  const BodyModel model = box_model(2);
  const Vec3 g(0, -9.81, -5.0);  // a z component must be ignored in 2D
  const double dt = 1e-3;
  BodyState s = initial_state(model);
  s.velocity = Vec3(2.0, 1.0, 0.0);
  s.angular_velocity = Vec3(0, 0, 3.0);
  for (int n = 0; n < 1000; ++n) advance_body(model, s, {}, g, n * dt, dt);
  const Vec3 exact = model.centre_of_mass + Vec3(2.0, 1.0 - 0.5 * 9.81, 0.0);
  const double error = (s.position - exact).norm();
  std::printf("free fall 2D, dt = 1e-3, t = 1 s: |X - X_exact| = %.3e m (predicted %.3e)\n", error,
              0.5 * 9.81 * dt);
  EXPECT_NEAR(error, 0.5 * 9.81 * dt, 1e-9);
  EXPECT_EQ(s.position.z(), 0.0);
  EXPECT_EQ(s.angular_velocity.x(), 0.0);
  EXPECT_EQ(s.angular_velocity.y(), 0.0);
  EXPECT_NEAR(s.angular_velocity.z(), 3.0, 1e-14);  // no torque: w_z constant
}

// 2D, constant torque: w = w0 + a t exactly; angle = w0 t + a t^2/2 + a t dt/2 (same
// semi-implicit term as the free fall). Tolerance: that term to 1e-9.
TEST(RigidNewtonEuler, ConstantTorqueSpinsUpAnalytically2D) {
  const BodyModel model = box_model(2);
  const double izz = model.inertia(2, 2), torque = 0.3 * izz;  // angular acceleration 0.3
  const double dt = 1e-3, w0 = 0.2;
  BodyState s = initial_state(model);
  s.angular_velocity = Vec3(0, 0, w0);
  BodyLoad load;
  load.torque = Vec3(0, 0, torque);
  double angle = 0.0, last = 0.0;
  for (int n = 0; n < 2000; ++n) {
    advance_body(model, s, load, Vec3::Zero(), n * dt, dt);
    const double now = 2.0 * std::atan2(s.orientation.z(), s.orientation.w());
    angle += std::remainder(now - last, 2.0 * std::numbers::pi);
    last = now;
  }
  const double t = 2.0;
  const double exact = w0 * t + 0.15 * t * t;
  std::printf(
      "2D constant torque: angle error %.3e rad (predicted a t dt/2 = %.3e), w error %.1e\n",
      angle - exact, 0.15 * t * dt, s.angular_velocity.z() - (w0 + 0.3 * t));
  EXPECT_NEAR(angle - exact, 0.15 * t * dt, 1e-9);
  EXPECT_NEAR(s.angular_velocity.z(), w0 + 0.3 * t, 1e-12);
}

// A constant w about a symmetric body's axis: the exact rotation-vector update turns by |w| dt
// per step exactly (error: rounding, 1e-10 rad after 1e4 steps); the first-order normalised one
// turns by 2 atan(|w| dt/2), an error predicted to 1e-9 of itself.
TEST(RigidNewtonEuler, QuaternionUpdatesTurnByTheExpectedAngle) {
  const BodyModel cube =
      make_body_model(lattice_box(3, 0.02, Vec3::Zero(), Vec3(0.1, 0.1, 0.1), 800.0));
  const Vec3 axis = Vec3(1, -2, 2).normalized();
  const double w = 5.0, dt = 1e-3;
  const int steps = 10000;
  for (auto update :
       {QuaternionUpdate::kExactRotationVector, QuaternionUpdate::kFirstOrderNormalised}) {
    BodyState s = initial_state(cube);
    s.angular_velocity = w * axis;
    IntegratorOptions options{RotationScheme::kExplicitEuler, update};
    for (int n = 0; n < steps; ++n) advance_body(cube, s, {}, Vec3::Zero(), n * dt, dt, options);
    const Eigen::AngleAxisd turned(s.orientation);
    const double total = std::fmod(w * dt * steps, 2 * std::numbers::pi);  // 50 rad
    const double per_step =
        update == QuaternionUpdate::kExactRotationVector ? w * dt : 2 * std::atan(0.5 * w * dt);
    const double expected = std::fmod(per_step * steps, 2 * std::numbers::pi);
    const double measured =
        turned.axis().dot(axis) > 0 ? turned.angle() : 2 * std::numbers::pi - turned.angle();
    std::printf("%s: angle error after 1e4 steps %.3e rad (expected %.3e)\n",
                update == QuaternionUpdate::kExactRotationVector ? "exact rotation vector"
                                                                 : "first-order normalised",
                measured - total, expected - total);
    EXPECT_NEAR(measured, expected, 1e-9);
  }
}

// The quaternion stays unit length over 1e5 steps (100 s, ~110 turns) of a tumble under a small
// torque with every scheme: each update ends with a normalisation, so only rounding (1e-12) is
// allowed. (|w| dt = 0.007: the explicit Euler scheme gains energy but stays finite here.)
TEST(RigidNewtonEuler, QuaternionStaysUnitOver1e5Steps) {
  const BodyModel model = box_model(3);
  const IntegratorOptions schemes[] = {
      {RotationScheme::kExplicitEuler, QuaternionUpdate::kFirstOrderNormalised},
      {RotationScheme::kExplicitEuler, QuaternionUpdate::kExactRotationVector},
      {RotationScheme::kMomentumSplitting, QuaternionUpdate::kExactRotationVector}};
  for (const IntegratorOptions& options : schemes) {
    BodyState s = initial_state(model);
    s.angular_velocity = Vec3(3.0, 4.0, 5.0);
    BodyLoad load;
    load.torque = Vec3(1e-4, -2e-4, 5e-5);  // |L| changes by ~10 % over the run
    double worst = 0.0;
    const double dt = 1e-3;
    for (int n = 0; n < 100000; ++n) {
      advance_body(model, s, load, Vec3::Zero(), n * dt, dt, options);
      const double deviation = std::abs(s.orientation.norm() - 1.0);
      worst = std::isfinite(deviation) ? std::max(worst, deviation) : 1.0;
    }
    const char* name = options.rotation == RotationScheme::kMomentumSplitting
                           ? "momentum splitting"
                           : (options.quaternion == QuaternionUpdate::kFirstOrderNormalised
                                  ? "explicit Euler, first-order normalised q"
                                  : "explicit Euler, exact rotation-vector q");
    std::printf("%s: max | |q| - 1 | over 1e5 steps = %.2e\n", name, worst);
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(RigidNewtonEuler, FixedBodyNeverMoves) {
  BodyModel model = box_model(3);
  model.motion = MotionKind::kFixed;
  BodyState s = initial_state(model);
  const BodyState start = s;
  BodyLoad load;
  load.force = Vec3(100, 200, 300);
  load.torque = Vec3(1, 2, 3);
  for (int n = 0; n < 100; ++n) advance_body(model, s, load, Vec3(0, 0, -9.81), n * 1e-3, 1e-3);
  EXPECT_EQ(s.position, start.position);
  EXPECT_EQ(s.orientation.coeffs(), start.orientation.coeffs());
  EXPECT_EQ(s.velocity.norm(), 0.0);
}

TEST(RigidNewtonEuler, PrescribedBodyFollowsItsMotion) {
  BodyModel model = box_model(3);
  model.motion = MotionKind::kPrescribed;
  model.prescribed = [](double t) {  // a gate lifted at free-fall speed, z = g t^2/2
    BodyState s;
    s.position = Vec3(1.0, 0.0, 0.5 * 9.81 * t * t);
    s.velocity = Vec3(0.0, 0.0, 9.81 * t);
    return s;
  };
  BodyState s = model.prescribed(0.0);
  for (int n = 0; n < 100; ++n) advance_body(model, s, {}, Vec3(0, 0, -9.81), n * 1e-3, 1e-3);
  EXPECT_NEAR(s.position.z(), 0.5 * 9.81 * 0.01, 1e-14);
  EXPECT_NEAR(s.velocity.z(), 9.81 * 0.1, 1e-14);
}

TEST(RigidNewtonEuler, ParticleKinematicsAreRigid) {
  const BodyModel model = box_model(3);
  BodyState s = initial_state(model);
  s.position = Vec3(1, 2, 3);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3(0, 1, 1).normalized()));
  s.velocity = Vec3(0.5, 0, 0);
  s.angular_velocity = Vec3(0, 0, 2.0);
  Vec3Array x, u;
  particle_positions(s, model.offset, x);
  particle_velocities(s, model.offset, u);
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 r = s.orientation * model.offset[i];
    worst = std::max(worst, (x[i] - (s.position + r)).norm());
    worst = std::max(worst, (u[i] - (s.velocity + s.angular_velocity.cross(r))).norm());
  }
  EXPECT_LT(worst, 1e-14);
}

}  // namespace
}  // namespace washout::rigid
