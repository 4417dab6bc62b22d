// The sinking box's landing load as the body report gives it (engine/cli/landing_load.hpp,
// docs/stability.md "Landing loads"), at two fixed time steps four times apart, d0 = 0.01 m:
// about 15 s on one thread. The raw one-step peak of the fluid load depends on dt (the water
// under the box is stopped in one step); the landing's impulse is what the physics sets, so it
// must agree across dt, and the report's impulses must balance the box's momentum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

struct Landing {
  double raw = 0, windowed = 0, impulse = 0, balance = 0, momentum = 0;
};

// The box's body report after a run at a fixed step dt; the momentum balance is
// J_fluid + J_contact - W D - M (v_after - v_landing), v_after read from the box's series.
Landing land(double dt) {
  char name[64];
  std::snprintf(name, sizeof name, "landing_impulse_dt_%g", dt);
  const cli::RunOutcome outcome =
      testing::run_scene("sinking_box_2d.lua", name,
                         {{"d0", "0.01"}, {"dt", std::to_string(dt)}, {"end_time", "0.35"}});
  EXPECT_EQ(outcome.bodies.size(), 1u);
  Landing l;
  if (outcome.bodies.empty()) return l;
  const cli::BodySummary& s = outcome.bodies[0].summary;
  EXPECT_FALSE(std::isnan(s.landing_time)) << "the box did not land";
  io::RunFileReader file(outcome.h5_path);
  const auto time = file.read_doubles("/bodies/box/time");
  const auto velocity = file.read_doubles("/bodies/box/velocity");
  // The row that ends the landing span: the step bound at landing start + D (dt divides D).
  const double start = s.landing_time - dt, end = start + s.landing_duration;
  std::size_t k = 0;
  while (k + 1 < time.size() && time[k] < end - 0.5 * dt) ++k;
  const double mass = s.weight / 9.81;
  l.raw = s.peak_force_vertical_one_step / s.weight;
  l.windowed = s.peak_force_vertical_windowed / s.weight;
  l.impulse = s.landing_impulse_fluid[1];
  l.momentum = mass * s.landing_velocity[1];
  l.balance = s.landing_impulse_fluid[1] + s.landing_impulse_contact[1] -
              s.weight * s.landing_duration - mass * (velocity[3 * k + 1] - s.landing_velocity[1]);
  std::printf(
      "dt = %.2e s: lands at %.4f s at %.3f m/s; raw one-step peak %.1f W, windowed (%.3g s) "
      "%.2f W, fluid impulse over %.3g s %.4f N s/m (M v = %.4f N s/m), momentum balance "
      "residual %.2e N s/m\n",
      dt, s.landing_time, s.landing_velocity[1], l.raw, s.load_window, l.windowed,
      s.landing_duration, l.impulse, l.momentum, l.balance);
  return l;
}

// Bounds:
//  - momentum balance: the report integrates the same per-step loads the integrator applied,
//    so J_f + J_c - W D = M dv holds to round-off (measured 1e-13 N s/m); 1e-9 M |v| allows
//    for summing some hundred rows;
//  - the fluid impulse over the landing at dt = 0.25 and 1 ms within 25 %: over dt = 0.25,
//    0.5, 0.75 and 1 ms it spreads by 19 %, 17 % and 22 % (largest over smallest, less one) at
//    d0 = 0.01, 0.0075 and 0.005 m, and by 18 %, 24 % and 27 % before the markers' bound on
//    extrapolation (docs/stability.md, "Landing loads", twelfth session), so any two steps can
//    be that far apart (measured here 16 %; 3 % before, a pair that happened to agree);
//  - the raw one-step peaks apart by more than the impulses (measured 2.4x against 1.19x): the
//    reason the raw peak is not the load to design with.
TEST(LandingImpulse, TheSinkingBoxsLandingImpulseDoesNotDependOnDt) {
  const Landing fine = land(0.00025), coarse = land(0.001);
  const double impulse_ratio = fine.impulse / coarse.impulse;
  const double raw_ratio = fine.raw / coarse.raw;
  std::printf(
      "dt 0.25 ms / 1 ms: raw one-step peak %.3f, windowed peak %.3f, landing impulse "
      "%.3f\n",
      raw_ratio, fine.windowed / coarse.windowed, impulse_ratio);
  for (const Landing& l : {fine, coarse}) {
    EXPECT_LT(l.impulse, 0.0);  // the water the box carries pushes it down as it stops
    EXPECT_LT(std::abs(l.balance), 1e-9 * std::abs(l.momentum));
  }
  EXPECT_LT(std::abs(impulse_ratio - 1.0), 0.25);
  EXPECT_GT(std::abs(std::log(raw_ratio)), std::abs(std::log(impulse_ratio)));
}

}  // namespace
}  // namespace washout
