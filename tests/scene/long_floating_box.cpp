// A box of density 500 released in still water settles at its Archimedes draft
// D = (rho_b / rho_w) H (scenes/floating_box_2d.lua, scenes/floating_box_3d.lua), at two
// resolutions each. Long: minutes per run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/box_draft.hpp"

namespace washout {
namespace {

struct Settled {
  double draft = 0, spread = 0, angle = 0;  // over the last second
  double first_spread = 0;                  // over the first second
};

// Standard deviation of the draft over the rows with t in [from, to].
double spread_over(const std::vector<double>& time, const std::vector<double>& drafts, double from,
                   double to) {
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::size_t r = 0; r < time.size(); ++r)
    if (time[r] >= from && time[r] <= to) sum += drafts[r], sum2 += drafts[r] * drafts[r], ++n;
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
}

// The draft D_m = level - bottom averaged over the last second: level from the water-height
// probes away from the box (interpolated to the body's rows), bottom = X - H/2.
Settled settle(const std::string& scene, int dim, double d0, double end_time) {
  char name[64];
  std::snprintf(name, sizeof name, "floating_%dd_%g", dim, d0);
  const cli::RunOutcome outcome = testing::run_scene(scene, name, {{"d0", std::to_string(d0)}});
  io::RunFileReader file(outcome.h5_path);
  const auto time = file.read_doubles("/bodies/box/time");
  const auto angle = file.read_doubles("/bodies/box/angle");
  std::vector<std::string> probes = dim == 2 ? std::vector<std::string>{"level_left", "level_right"}
                                             : std::vector<std::string>{"level"};
  const auto drafts = testing::box_draft(file, probes, dim - 1, 0.05);
  Settled s;
  int n = 0;
  for (std::size_t r = 0; r < time.size(); ++r) {
    if (time[r] < end_time - 1.0) continue;
    s.draft += drafts[r];
    s.angle = std::max(s.angle, std::abs(angle[r]));
    ++n;
  }
  s.draft /= n;
  s.spread = spread_over(time, drafts, end_time - 1.0, end_time);
  s.first_spread = spread_over(time, drafts, 0.0, 1.0);
  return s;
}

// Bounds: the mean draft within one particle spacing of D (the free surface is resolved to
// d0: P = 0 sits on the surface particles' centres, d0/2 below the water's edge, see
// test_floating_box.cpp); upright: roll below 0.05 rad; settling: the heave decays, its standard
// deviation over the last second below 0.7 of that over the first. The tanks are closed and
// only 0.2 m (2D) or 0.1 m (3D) wider than the box on each side, so the waves the heave radiates
// come back within a period and the heave decays slowly: measured 0.41 and 0.53 in 2D over 3 s,
// 0.56 and 0.57 in 3D over 2 s (docs/bodies.md). An undamped coupling would keep the ratio near
// 1, an unstable one above it. (An absolute bound of 0.1 D on the last second's spread, as an
// open tank would allow, is missed by all four: 0.0052 to 0.0074 m.)
void expect_settled(const std::string& scene, int dim, double d0, double end_time,
                    double decay_bound) {
  const double D = 0.05;
  const Settled s = settle(scene, dim, d0, end_time);
  std::printf(
      "%dD, d0 = %.4f m: draft %.4f m against D = %.4f m: error %+.1f %% (bound %.0f %%), "
      "heave spread %.4f m in the first second, %.4f m in the last (ratio %.2f, bound %.2f), "
      "largest roll %.3f rad\n",
      dim, d0, s.draft, D, 100 * (s.draft / D - 1), 100 * d0 / D, s.first_spread, s.spread,
      s.spread / s.first_spread, decay_bound, s.angle);
  EXPECT_LT(std::abs(s.draft - D), d0);
  EXPECT_LT(s.spread, decay_bound * s.first_spread);
  EXPECT_LT(s.angle, 0.05);
}

TEST(FloatingBoxLong, SettlesAtTheArchimedesDraft2D) {
  for (double d0 : {0.01, 0.005}) expect_settled("floating_box_2d.lua", 2, d0, 3.0, 0.7);
}

TEST(FloatingBoxLong, SettlesAtTheArchimedesDraft3D) {
  // 3D: 0.85. With the Wendland pair force (fifteenth session) the box at d0 = 0.01 m sits at
  // -2.6 % of D (+5.8 % before) and its heave decays more slowly over these two seconds: ratio
  // 0.75 (0.59 at d0 = 0.02 m; 0.56 and 0.57 with the cubic spline). 0.85 still tells a
  // decaying heave from an undamped one (near 1).
  for (double d0 : {0.02, 0.01}) expect_settled("floating_box_3d.lua", 3, d0, 2.0, 0.85);
}

}  // namespace
}  // namespace washout
