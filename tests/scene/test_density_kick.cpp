// density_kick = "positions" (engine/fluid/density_kick.cpp): the density term moves the
// particles but does not stay in their velocity, so that its per-step kicks do not add up to
// motion in still water (docs/stability.md, forty-sixth session).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

struct StillWater {
  double largest_speed = 0.0;  // over the fluid and the frames from `from` on [m/s]
  double pressure = 0.0;  // the scene's score: last frame, RMS of (P - rho g (H - y)) / (rho g H)
};

StillWater still_tank(const std::string& name, const std::string& density_kick, double end_time,
                      double from) {
  const auto out = testing::run_scene("hydrostatic_2d.lua", name,
                                      {{"d0", "0.01"},  // H/d0 = 10
                                       {"end_time", std::to_string(end_time)},
                                       {"output_interval", "0.5"},
                                       {"density_kick", density_kick}});
  if (out.exit_code != 0) return {1e9, 1e9};
  StillWater s;
  s.pressure = testing::score(out, "pressure");
  io::RunFileReader run(out.h5_path);
  for (std::size_t k = 0; k < run.frame_count(); ++k) {
    const auto f = run.read_frame(k);
    if (f.time < from - 1e-9) continue;
    for (std::size_t i = 0; i < f.count; ++i)
      if (f.kind[i] == 0)
        s.largest_speed =
            std::max(s.largest_speed, std::hypot(f.velocity[2 * i], f.velocity[2 * i + 1]));
  }
  return s;
}

// The 2D tank ten particles deep, at the default step: with the density term's kick kept in the
// velocity the water churns from about 3 s on (35 mm/s at 4 s, 67 mm/s at 10 s); with it taken
// back out after the move the largest speed stays at 0.8-1.0 mm/s through 10 s and the interior
// pressure error at 0.33 % of rho g H (0.55 % with the kick kept). Bounds: 3 mm/s over 3-6 s
// (three times the measurement, a tenth of the churn) and 0.5 %.
TEST(DensityKick, PositionsKeepTheShallowStillTankStill) {
  const StillWater positions = still_tank("density_kick_positions", "positions", 6.0, 3.0);
  const StillWater velocity = still_tank("density_kick_velocity", "velocity", 6.0, 3.0);
  std::printf(
      "2D still tank, H/d0 = 10, 3-6 s: largest speed %.2f mm/s with density_kick = positions "
      "(bound 3), %.2f mm/s with velocity (the default, printed only); pressure error at 6 s "
      "%.3f %% / %.3f %% of rho g H (bound 0.5 %%)\n",
      1e3 * positions.largest_speed, 1e3 * velocity.largest_speed, 100 * positions.pressure,
      100 * velocity.pressure);
  EXPECT_LT(positions.largest_speed, 3e-3);
  EXPECT_LT(positions.pressure, 0.005);
}

// With alpha = 0 the density term is absent: its pressure is 0, the two corrector passes give the
// same velocity, the kick is 0 and the run is the default's to the bit.
TEST(DensityKick, WithoutTheDensityTermTheRunIsTheDefaults) {
  const lua::Overrides common = {{"d0", "0.01"}, {"end_time", "0.3"}, {"alpha", "0"}};
  lua::Overrides positions = common, velocity = common;
  positions.push_back({"density_kick", "positions"});
  const auto a =
      testing::run_scene("hydrostatic_2d.lua", "density_kick_alpha0_positions", positions);
  const auto b = testing::run_scene("hydrostatic_2d.lua", "density_kick_alpha0_velocity", velocity);
  ASSERT_EQ(a.exit_code, 0);
  ASSERT_EQ(b.exit_code, 0);
  const io::RunFileReader run_a(a.h5_path), run_b(b.h5_path);
  const auto fa = run_a.read_frame(run_a.frame_count() - 1);
  const auto fb = run_b.read_frame(run_b.frame_count() - 1);
  ASSERT_EQ(fa.position.size(), fb.position.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < fa.position.size(); ++k)
    largest = std::max(largest, std::abs(fa.position[k] - fb.position[k]));
  std::printf("alpha = 0, 0.3 s: largest position difference between the two forms %.3g m\n",
              largest);
  EXPECT_EQ(largest, 0.0);
  EXPECT_EQ(fa.pressure, fb.pressure);
}

// The bodies' coupling with the pressure keeps the density term in it: refused before the run,
// naming the parameter.
TEST(DensityKick, IsRefusedWithDynamicBodies) {
  const auto out =
      testing::run_scene("floating_box_2d.lua", "density_kick_bodies",
                         {{"d0", "0.01"}, {"end_time", "0.1"}, {"density_kick", "positions"}},
                         /*expect_success=*/false);
  EXPECT_EQ(out.exit_code, 1);
  EXPECT_NE(out.error.find("density_kick"), std::string::npos) << out.error;
  EXPECT_NE(out.error.find("dynamic bodies"), std::string::npos) << out.error;
}

}  // namespace
}  // namespace washout
