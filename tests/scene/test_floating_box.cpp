// A box of density 500 held in still water at its Archimedes draft D = (rho_b / rho_w) H
// (scenes/floating_box_2d.lua with motion = "fixed"): the fluid's pressure on it must carry its
// weight, F_f = M g, at two resolutions. This is the static half of the floating-box check;
// the release-and-settle half is tests/scene/long_floating_box.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/box_draft.hpp"

namespace washout {
namespace {

// P = 0 holds at the water's surface (the ghost form, docs/method.md), so the pressure carries
// the weight at the Archimedes draft: measured -0.85 % at d0 = 0.01 m (D = 5 d0) and -0.53 % at
// d0 = 0.005 m. With P = 0 on the surface particles' centres, d0/2 below the water's edge, the
// draft came out short by d0/2: F_f = M g (1 - d0 / (2 D)), -10 % and -5 % (the line printed
// "against M g (1 - d0/2D)" shows that form's expectation). Bound: |F_f / (M g) - 1| <= d0 / D,
// one particle spacing of draft, and the error must shrink with d0. The horizontal force and
// the torque vanish by symmetry (0.1 %).
TEST(FloatingBox, PressureCarriesTheWeightAtTheArchimedesDraft) {
  const double B = 0.2, H = 0.1, rho_b = 500.0, rho_w = 1000.0, g = 9.81;
  const double D = rho_b / rho_w * H, weight = rho_b * B * H * g;
  double previous = 1.0;
  for (double d0 : {0.01, 0.005}) {
    char name[64];
    std::snprintf(name, sizeof name, "floating_box_fixed_%g", d0);
    const cli::RunOutcome outcome = testing::run_scene("floating_box_2d.lua", name,
                                                       {{"d0", std::to_string(d0)},
                                                        {"motion", "fixed"},
                                                        {"start_draft", std::to_string(D)},
                                                        {"end_time", "0.5"},
                                                        {"output_interval", "0.1"}});
    io::RunFileReader file(outcome.h5_path);
    const auto time = file.read_doubles("/bodies/box/time");
    const auto force = file.read_doubles("/bodies/box/force_fluid");
    const auto torque = file.read_doubles("/bodies/box/torque_fluid");
    double fy = 0, fx = 0, mz = 0;
    int n = 0;
    for (std::size_t r = 0; r < time.size(); ++r) {
      if (time[r] < 0.1) continue;  // the start-up of the fluid's discrete equilibrium
      fx += force[3 * r], fy += force[3 * r + 1], mz += torque[3 * r + 2];
      ++n;
    }
    fx /= n, fy /= n, mz /= n;
    const double error = fy / weight - 1.0;
    std::printf(
        "d0 = %.3f m: F_f = %.3f N/m, M g = %.3f N/m: error %+.2f %% (bound %.0f %%); "
        "against M g (1 - d0/2D): %+.2f %%; F_x / M g = %.1e, M_z / (M g B) = %.1e\n",
        d0, fy, weight, 100 * error, 100 * d0 / D, 100 * (fy / (weight * (1 - 0.5 * d0 / D)) - 1),
        fx / weight, mz / (weight * B));
    EXPECT_LT(std::abs(error), d0 / D);
    EXPECT_LT(std::abs(error), std::abs(previous)) << "no convergence with d0";
    EXPECT_LT(std::abs(fx) / weight, 1e-3);
    EXPECT_LT(std::abs(mz) / (weight * B), 1e-3);
    previous = error;
  }
}

// Released at a draft of 0.03 m (equilibrium D = 0.05 m), the box must heave like a lightly
// damped oscillator about D: the solved-together pressure and body velocities
// (implicit_body_coupling.hpp) keep it in the water, where METHOD.md's explicit step, with an
// added mass about twice the box's, left the water within ten steps. Bounds over the first
// second at d0 = 0.01 m (1.3 heave periods): the run completes; the deepest draft stays below
// the undamped overshoot 2 D - 0.03 = 0.07 m plus d0 (the surface is resolved to d0) and
// reaches at least D - d0 (it sinks to equilibrium); the box never rises above its release
// draft by more than d0; the roll stays below 0.05 rad. The draft is the water level from the
// probes beside the box less the box's bottom.
TEST(FloatingBox, ReleasedBoxHeavesAboutTheArchimedesDraft) {
  const double D = 0.05, start = 0.03, d0 = 0.01, half_height = 0.05;
  const cli::RunOutcome outcome = testing::run_scene(
      "floating_box_2d.lua", "floating_box_released",
      {{"d0", std::to_string(d0)}, {"end_time", "1.0"}, {"output_interval", "0.1"}});
  ASSERT_EQ(outcome.exit_code, 0);
  io::RunFileReader file(outcome.h5_path);
  const auto time = file.read_doubles("/bodies/box/time");
  const auto angle = file.read_doubles("/bodies/box/angle");
  const auto drafts = testing::box_draft(file, {"level_left", "level_right"}, 1, half_height);
  double deepest = 0, shallowest = 1, roll = 0;
  for (std::size_t r = 0; r < time.size(); ++r) {
    const double draft = drafts[r];
    deepest = std::max(deepest, draft);
    if (time[r] > 0.2) shallowest = std::min(shallowest, draft);
    roll = std::max(roll, std::abs(angle[r]));
  }
  std::printf(
      "released at draft %.3f m: deepest %.4f m (bounds %.3f to %.3f), shallowest after 0.2 s "
      "%.4f m (bound > %.3f), largest roll %.4f rad\n",
      start, deepest, D - d0, 2 * D - start + d0, shallowest, start - d0, roll);
  EXPECT_LT(deepest, 2 * D - start + d0);
  EXPECT_GT(deepest, D - d0);
  EXPECT_GT(shallowest, start - d0);
  EXPECT_LT(roll, 0.05);
}

}  // namespace
}  // namespace washout
