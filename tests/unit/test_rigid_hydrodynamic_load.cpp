// Hydrodynamic load F_f = sum -P n dS, M_f = sum r x (-P n dS): zero for a constant pressure on
// a closed surface, buoyancy rho g V for a hydrostatic pressure, and the right torque arm.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/rigid/body_state.hpp"
#include "engine/rigid/hydrodynamic_load.hpp"
#include "engine/rigid/lattice_body.hpp"

namespace washout::rigid {
namespace {

constexpr double kRho = 1000.0, kG = 9.81;

struct Surface {
  Vec3Array position, normal;
  std::vector<double> area;
};

// The box's surface particles in a pose (rotated about an oblique axis), as the engine sees it.
Surface posed_surface(const BodyModel& model, const BodyState& state) {
  Surface s;
  surface_positions_and_normals(model, state, s.position, s.normal);
  s.area = model.surface_area;
  return s;
}

BodyState tilted(const BodyModel& model) {
  BodyState state = initial_state(model);
  state.position = Vec3(0.4, -0.2, -0.5);
  state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  return state;
}

// sum n dS = 0 holds exactly for the lattice box's vector areas, so a constant pressure gives
// zero force and torque up to rounding: tolerance 1e-12 of P A.
TEST(RigidHydrodynamicLoad, ConstantPressureOnClosedSurfaceGivesNothing) {
  BodyModel m = make_body_model(lattice_box(3, 0.01, Vec3::Zero(), Vec3(0.3, 0.2, 0.1), 500.0));
  const BodyState state = tilted(m);
  const Surface s = posed_surface(m, state);
  const std::vector<double> pressure(s.area.size(), 12345.0);
  const BodyLoad load = hydrodynamic_load(pressure, s.position, s.normal, s.area, state.position);
  const double scale = 12345.0 * 2 * (0.3 * 0.2 + 0.3 * 0.1 + 0.2 * 0.1);
  std::printf("constant pressure: |F|/(P A) = %.2e, |M|/(P A L) = %.2e\n",
              load.force.norm() / scale, load.torque.norm() / (scale * 0.3));
  EXPECT_LT(load.force.norm() / scale, 1e-12);
  EXPECT_LT(load.torque.norm() / (scale * 0.3), 1e-12);
}

// Hydrostatic P = rho g (H - z) sampled at the surface particles, which sit d0/2 inside the
// faces: the top-bottom pressure difference is rho g (c - d0), so the buoyancy is short by
// exactly d0/c (first order, halves with d0). Tolerance: that prediction to 1e-9.
TEST(RigidHydrodynamicLoad, HydrostaticPressureGivesBuoyancyToFirstOrderInD0) {
  const double a = 0.3, b = 0.2, c = 0.1, depth = 1.0;
  for (double d0 : {0.01, 0.005}) {
    BodyModel m = make_body_model(lattice_box(3, d0, Vec3(0, 0, 0.2), Vec3(a, b, 0.2 + c), 500.0));
    const BodyState state = initial_state(m);
    const Surface s = posed_surface(m, state);
    std::vector<double> pressure(s.area.size());
    for (std::size_t i = 0; i < pressure.size(); ++i)
      pressure[i] = kRho * kG * (depth - s.position.z[i]);
    const BodyLoad load = hydrodynamic_load(pressure, s.position, s.normal, s.area, state.position);
    const double buoyancy = kRho * kG * a * b * c;
    const double error = (load.force - Vec3(0, 0, buoyancy)).norm() / buoyancy;
    std::printf("buoyancy, d0 = %.3f: relative error %.4f (predicted d0/c = %.4f), |M| = %.1e\n",
                d0, error, d0 / c, load.torque.norm());
    EXPECT_NEAR(error, d0 / c, 1e-9);
    EXPECT_LT(load.torque.norm(), 1e-9 * buoyancy * a);
  }
}

// With the pressure taken on the faces themselves (each surface particle moved d0/2 out along
// its normal, as an extrapolation to the wall would do) the buoyancy is exact for any pose;
// about a point d off the centre the torque is (C - X) x F = -d x F. Tolerance 1e-12.
TEST(RigidHydrodynamicLoad, PressureOnTheFacesGivesExactBuoyancyAndTorqueArm) {
  const double d0 = 0.01;
  BodyModel m = make_body_model(lattice_box(3, d0, Vec3::Zero(), Vec3(0.3, 0.2, 0.1), 500.0));
  const BodyState state = tilted(m);
  const Surface s = posed_surface(m, state);
  std::vector<double> pressure(s.area.size());
  Vec3Array on_face = s.position;
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    // A corner particle's normal is diagonal; its vector area splits per face, and the pressure
    // is linear, so sampling at the particle moved by d0/2 along each face normal in turn is the
    // same as sampling at x + (d0/2) sum of the face normals = x + (d0/2) n_i |n_i|_1-ish.
    // For a box: x_face = x + (d0/2) * sum_faces n_face, with n_face the signs of n_i.
    const Vec3 local = state.orientation.conjugate() * s.normal[i];
    Vec3 faces = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      if (std::abs(local[k]) > 1e-9) faces[k] = local[k] > 0 ? 1.0 : -1.0;
    const Vec3 x_face = s.position[i] + 0.5 * d0 * (state.orientation * faces);
    pressure[i] = kRho * kG * (1.0 - x_face.z());
    on_face.set(i, x_face);
  }
  const double buoyancy = kRho * kG * 0.3 * 0.2 * 0.1;
  const BodyLoad load = hydrodynamic_load(pressure, s.position, s.normal, s.area, state.position);
  const Vec3 d(0.05, -0.02, 0.03);
  const BodyLoad about_d =
      hydrodynamic_load(pressure, s.position, s.normal, s.area, state.position + d);
  const double force_error = (load.force - Vec3(0, 0, buoyancy)).norm() / buoyancy;
  const double torque_error =
      (about_d.torque - (-d).cross(load.force)).norm() / (buoyancy * d.norm());
  std::printf("pressure on faces: buoyancy error %.2e, torque-arm error %.2e, |M about X| %.1e\n",
              force_error, torque_error, load.torque.norm());
  EXPECT_LT(force_error, 1e-12);
  EXPECT_LT(load.torque.norm(), 1e-12 * buoyancy);
  EXPECT_LT(torque_error, 1e-12);
}

// 2D: a rectangle under water, per metre of thickness: rho g a b (1 - d0/b) upward, no torque.
TEST(RigidHydrodynamicLoad, BuoyancyOfARectangle2D) {
  const double a = 0.3, b = 0.03, d0 = 0.005;
  BodyModel m = make_body_model(lattice_box(2, d0, Vec3(0, 0.1, 0), Vec3(a, 0.1 + b, 0), 900.0));
  const BodyState state = initial_state(m);
  const Surface s = posed_surface(m, state);
  std::vector<double> pressure(s.area.size());
  for (std::size_t i = 0; i < pressure.size(); ++i)
    pressure[i] = kRho * kG * (0.5 - s.position.y[i]);  // 2D: y is up
  const BodyLoad load = hydrodynamic_load(pressure, s.position, s.normal, s.area, state.position);
  const double buoyancy = kRho * kG * a * b;
  const double error = (load.force - Vec3(0, buoyancy, 0)).norm() / buoyancy;
  std::printf("2D buoyancy: relative error %.4f (predicted d0/b = %.4f)\n", error, d0 / b);
  EXPECT_NEAR(error, d0 / b, 1e-9);
  EXPECT_LT(load.torque.norm(), 1e-9 * buoyancy * a);
}

TEST(RigidHydrodynamicLoad, RejectsArraysOfDifferentLengths) {
  Vec3Array x, n;
  x.resize(2);
  n.resize(2);
  std::vector<double> p(3, 0.0), area(2, 1.0);
  EXPECT_THROW(hydrodynamic_load(p, x, n, area, Vec3::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace washout::rigid
