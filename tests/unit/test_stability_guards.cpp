// The units behind the stability guards (docs/stability.md): the time step's limits, the
// mechanical energy of the fluid, the work bound of moving boundaries and the energy budget.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/fluid/density_relaxation.hpp"
#include "engine/sim/energy_budget.hpp"
#include "engine/sim/time_step_limits.hpp"

namespace washout {
namespace {

// Each limit wins where it is the smallest, and the reported name says which.
TEST(TimeStepLimits, TheSmallestLimitSetsTheStepAndIsNamed) {
  TimeStepInputs in;
  in.h = 0.012, in.cfl = 0.2, in.viscous_number = 0.125, in.dt_max = 1e-3;
  in.time = 0, in.until = 1.0;
  EXPECT_EQ(choose_time_step(in).limit, StepLimit::dt_max);  // at rest, inviscid, no gravity
  in.max_speed = 3.0;                                        // cfl h / u = 8e-4
  auto c = choose_time_step(in);
  EXPECT_EQ(c.limit, StepLimit::advective);
  EXPECT_DOUBLE_EQ(c.dt, 0.2 * 0.012 / 3.0);
  in.max_viscosity = 1.0;  // 0.125 h^2 / nu = 1.8e-5
  c = choose_time_step(in);
  EXPECT_EQ(c.limit, StepLimit::viscous);
  EXPECT_DOUBLE_EQ(c.dt, 0.125 * 0.012 * 0.012);
  in.max_viscosity = 0, in.max_speed = 0, in.gravity = 1e5;  // 0.25 sqrt(h/g) = 8.7e-5
  c = choose_time_step(in);
  EXPECT_EQ(c.limit, StepLimit::gravity);
  EXPECT_DOUBLE_EQ(c.dt, 0.25 * std::sqrt(0.012 / 1e5));
  in.gravity = 0, in.until = 1.5e-3;  // two equal steps land on the frame
  c = choose_time_step(in);
  EXPECT_EQ(c.limit, StepLimit::frame);
  EXPECT_DOUBLE_EQ(c.dt, 0.75e-3);
  EXPECT_DOUBLE_EQ(c.unlanded_dt, 1e-3);  // the step the limits gave before the landing
  in.fixed_dt = 2e-4;
  EXPECT_EQ(choose_time_step(in).limit, StepLimit::fixed);
  EXPECT_DOUBLE_EQ(choose_time_step(in).unlanded_dt, 2e-4);
  EXPECT_STREQ(step_limit_name(StepLimit::advective), "cfl");
}

Particles column(int n, double d0) {
  Particles p;
  p.dim = 2;
  for (int k = 0; k < n; ++k)
    p.add(ParticleKind::Fluid, Vec3(0.1 * k, (k + 0.5) * d0, 0), Vec3(0.3 * k, -0.2, 0), -1);
  p.fluid_count = n;
  return p;
}

// alpha per unit time: a step shorter than the reference relaxes the same fraction of the
// density error per second (alpha_step / dt = alpha / dt_reference), so n steps of dt_reference / n
// remove what one reference step removes to first order; at the reference step and above, alpha
// is used as given, to the bit.
TEST(DensityRelaxation, ShorterStepsRelaxAtTheReferenceRateInTime) {
  const double alpha = 0.05, reference = 7e-4;
  EXPECT_EQ(density_relaxation_per_time(alpha, reference, reference), alpha);
  EXPECT_EQ(density_relaxation_per_time(alpha, 3 * reference, reference), alpha);
  EXPECT_EQ(density_relaxation_per_time(alpha, 1e-4, 0.0), alpha);  // no reference: as given
  for (const int n : {2, 10, 100}) {
    const double dt = reference / n, a = density_relaxation_per_time(alpha, dt, reference);
    EXPECT_NEAR(a / dt, alpha / reference, 1e-12 * alpha / reference);
    // The error left after one reference step's time, (1 - a)^n, against 1 - alpha: the rate in
    // time is the same, the per-step compounding differs at second order (alpha^2 / 2).
    const double left = std::pow(1.0 - a, n);
    std::printf("n = %3d steps: error left %.6f (one reference step: %.6f)\n", n, left,
                1.0 - alpha);
    EXPECT_NEAR(left, 1.0 - alpha, 0.5 * alpha * alpha);
  }
  // Per step, the same alpha at a tenth of the step removes (1 - 0.95^10) = 40 % in that time.
  EXPECT_GT(1.0 - std::pow(1.0 - alpha, 10), 7.5 * alpha);
}

// Free fall conserves kinetic plus potential energy: moving every particle along its exact
// ballistic path leaves E unchanged (to round-off), and E has the right value at the start.
TEST(EnergyBudget, FreeFallConservesMechanicalEnergy) {
  const double m = 0.1, g = 9.81;
  Particles p = column(20, 0.01);
  const Vec3 gravity(0, -g, 0);
  double expected = 0;
  for (int k = 0; k < 20; ++k)
    expected += m * (0.5 * (std::pow(0.3 * k, 2) + 0.04) + g * (k + 0.5) * 0.01);
  const double e0 = fluid_mechanical_energy(p, m, gravity);
  EXPECT_NEAR(e0, expected, 1e-12 * expected);
  const double t = 0.37;
  for (std::size_t i = 0; i < p.fluid_count; ++i) {
    p.position[0][i] += p.velocity[0][i] * t;
    p.position[1][i] += p.velocity[1][i] * t - 0.5 * g * t * t;
    p.velocity[1][i] -= g * t;
  }
  const double e1 = fluid_mechanical_energy(p, m, gravity);
  std::printf("E(0) = %.6f J, after %.2f s of free fall %.6f J\n", e0, t, e1);
  EXPECT_NEAR(e1, e0, 1e-12 * e0);
}

// Only the first layer of moving boundary particles, and only their normal speed, can work on
// the fluid: a gate lifted along its face does none, a piston pushing along its normal does.
TEST(EnergyBudget, WorkBoundCountsNormalMotionOfMovingBoundariesOnly) {
  const double d0 = 0.01, P = 2000.0;
  Particles p;
  p.dim = 2;
  p.fluid_count = 0;
  for (int layer = 0; layer < 3; ++layer)
    for (int k = 0; k < 10; ++k)
      p.add(ParticleKind::MovingWall, Vec3(-(layer + 0.5) * d0, (k + 0.5) * d0, 0), Vec3(0, 1.5, 0),
            0, Vec3(1, 0, 0), (layer + 0.5) * d0);
  EXPECT_EQ(moving_boundary_power_bound(p, d0, P), 0.0);              // lifted along its face
  for (std::size_t w = 0; w < p.size(); ++w) p.velocity[0][w] = 0.5;  // and pushed at 0.5 m/s
  const double power = moving_boundary_power_bound(p, d0, P);
  EXPECT_NEAR(power, 10 * P * d0 * 0.5, 1e-12);  // the first layer's 10 particles only
  for (std::size_t w = 0; w < p.size(); ++w)
    p.kind[w] = static_cast<std::uint8_t>(ParticleKind::FixedWall);
  EXPECT_EQ(moving_boundary_power_bound(p, d0, P), 0.0);
}

// The budget: E(0) + work bound + tolerance x scale is allowed, anything above is an excess that
// the message quantifies.
TEST(EnergyBudget, ExcessAboveWorkAndToleranceFiresWithFigures) {
  EnergyBudget budget;
  budget.start(100.0, 50.0, 0.1);  // allowed: 100 + 5
  EXPECT_LT(budget.excess(104.9), 0.0);
  EXPECT_GT(budget.excess(105.1), 0.0);
  budget.add_work_bound(0.01, 300.0);  // + 3 J
  EXPECT_LT(budget.excess(107.9), 0.0);
  EXPECT_NEAR(budget.excess(110.0), 2.0, 1e-12);
  const std::string m = budget.describe(110.0, 0.25);
  std::printf("%s\n", m.c_str());
  EXPECT_NE(m.find("energy gain"), std::string::npos);
  EXPECT_NE(m.find("t = 0.25 s"), std::string::npos);
  EXPECT_NE(m.find("energy_gain_limit"), std::string::npos);
}

}  // namespace
}  // namespace washout
