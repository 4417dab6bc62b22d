// Water at rest: the pressure must settle to rho g (H - y) and no particle may enter a wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

struct HydrostaticError {
  double max_interior = 0.0;  // max |P - rho g (H - y)| / (rho g H) over interior particles
  double max_speed = 0.0;
};

HydrostaticError measure(const io::FrameData& f, double H, double d0) {
  HydrostaticError e;
  const double rho_g_H = 1000.0 * 9.81 * H;
  const int up = f.dim - 1;
  for (std::size_t i = 0; i < f.count; ++i) {
    if (f.kind[i] != 0) continue;
    const double y = f.position[i * f.dim + up];
    double s2 = 0.0;
    for (int a = 0; a < f.dim; ++a) s2 += std::pow(f.velocity[i * f.dim + a], 2);
    e.max_speed = std::max(e.max_speed, std::sqrt(s2));
    // Interior: more than a kernel support (3 d0) below the free surface.
    if (y > H - 3.0 * d0) continue;
    e.max_interior =
        std::max(e.max_interior, std::abs(f.pressure[i] - 1000.0 * 9.81 * (H - y)) / rho_g_H);
  }
  return e;
}

// Runs hydrostatic_2d.lua with the settings to t_end and measures its last frame.
struct Settled {
  HydrostaticError error;
  long wall_crossings = 0;
};
Settled run_2d_until(const std::string& name, lua::Overrides settings, double t_end, double H,
                     double d0) {
  settings.push_back({"end_time", std::to_string(t_end)});
  const auto out = testing::run_scene("hydrostatic_2d.lua", name, settings);
  EXPECT_EQ(out.exit_code, 0);
  if (out.exit_code != 0) return {{1e9, 1e9}, 0};
  io::RunFileReader run(out.h5_path);
  const auto frame = run.read_frame(run.frame_count() - 1);
  EXPECT_NEAR(frame.time, t_end, 1e-9);
  return {measure(frame, H, d0), out.summary.wall_crossings};
}

TEST(Hydrostatic, Pressure2dAfterOneSecondWithinTwoPercent) {
  // d0 = H/40. P = 0 is imposed on the top particle layer, which sits d0/2 below the nominal
  // surface: a first-order offset of d0/(2H) = 1.25 % of rho g H. 2 % leaves 0.75 % for the
  // particle noise; the issue asks for 2 %.
  const double H = 0.1, d0 = H / 40;
  const auto [e, wall_crossings] =
      run_2d_until("hydrostatic_2d_fine", {{"d0", std::to_string(d0)}}, 1.0, H, d0);
  std::printf(
      "hydrostatic 2D, d0 = H/40, t = 1 s: max interior error %.4f rho g H, max speed %.2e m/s, "
      "wall crossings %ld\n",
      e.max_interior, e.max_speed, wall_crossings);
  EXPECT_LT(e.max_interior, 0.02);
  // At rest to 2 % of the wave speed: a disturbance that starts at the corners where the
  // surface meets the side walls grows from about 0.5 s under either wall form (max speed at 1 s
  // 7.0e-3 m/s with the Neumann walls, 1.1e-2 m/s with the dynamic ones, the default since the
  // seventh session; 3-5e-2 m/s at 1.5-2 s, then it decays): docs/stability.md, still water.
  EXPECT_LT(e.max_speed, 0.02 * std::sqrt(9.81 * H));
  EXPECT_EQ(wall_crossings, 0);
}

TEST(Hydrostatic, Pressure2dCoarse) {
  // d0 = H/20: the surface offset alone is 2.5 %; 3.5 % bounds it with the same noise margin.
  const double H = 0.1, d0 = H / 20;
  const auto out = testing::run_scene("hydrostatic_2d.lua", "hydrostatic_2d_coarse", {});
  ASSERT_EQ(out.exit_code, 0);
  io::RunFileReader run(out.h5_path);
  const auto e = measure(run.read_frame(run.frame_count() - 1), H, d0);
  std::printf(
      "hydrostatic 2D, d0 = H/20, t = 1 s: max interior error %.4f rho g H, max speed %.2e m/s\n",
      e.max_interior, e.max_speed);
  EXPECT_LT(e.max_interior, 0.035);
  EXPECT_EQ(out.summary.wall_crossings, 0);
  // The stats series: one row per step, cumulative wall time non-decreasing.
  const auto steps = run.read_doubles("/stats/time");
  EXPECT_EQ(steps.size(), static_cast<std::size_t>(out.summary.steps));
}

// A quarter of the default step (dt_max = 0.25 ms, H/20, 2 s). Taken per step, alpha relaxed the
// density error four times faster in time and still water churned: max interior error 3.95 % of
// rho g H and 51 mm/s at 2 s (5.1 % and 81 mm/s at 3 s). alpha per unit time (the default,
// engine/fluid/density_relaxation.hpp): 0.18 % and 2.9 mm/s (at the default step 0.16 % and
// 0.6 mm/s). Bounds: the 0.5 % and 1 cm/s, a fifth of what the per-step form gives.
TEST(Hydrostatic, AQuarterOfTheStepStaysAtRest) {
  const double H = 0.1, d0 = H / 20;
  const auto e =
      run_2d_until("hydrostatic_2d_quarter_step", {{"dt_max", "0.00025"}}, 2.0, H, d0).error;
  std::printf(
      "hydrostatic 2D, d0 = H/20, dt = 0.25 ms, t = 2 s: max interior error %.4f rho g H, "
      "max speed %.2e m/s\n",
      e.max_interior, e.max_speed);
  EXPECT_LT(e.max_interior, 0.005);
  EXPECT_LT(e.max_speed, 0.01);
}

TEST(Hydrostatic, Pressure3dShortTime) {
  // 3D, d0 = H/10 for CI time. Known limitation (docs/method.md): in 3D still water a
  // near-wall disturbance grows after about 0.15 s, so this checks t = 0.1 s only, where the
  // first-order surface offset is d0/(2H) = 5 %; 6 % bounds it.
  const double H = 0.1, d0 = 0.01;
  const auto out = testing::run_scene("hydrostatic_3d.lua", "hydrostatic_3d",
                                      {{"end_time", "0.1"}, {"output_interval", "0.05"}});
  ASSERT_EQ(out.exit_code, 0);
  io::RunFileReader run(out.h5_path);
  const auto e = measure(run.read_frame(run.frame_count() - 1), H, d0);
  std::printf(
      "hydrostatic 3D, d0 = H/10, t = 0.1 s: max interior error %.4f rho g H, max speed %.2e m/s\n",
      e.max_interior, e.max_speed);
  EXPECT_LT(e.max_interior, 0.06);
  EXPECT_EQ(out.summary.wall_crossings, 0);
}

}  // namespace
}  // namespace washout
