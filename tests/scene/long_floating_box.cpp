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
  double draft = 0, angle = 0;  // over the last `window` seconds
  double spread = 0;            // of the box's height over the last second
  double first_spread = 0;      // over the first second
};

// Standard deviation of a series over the rows with t in [from, to].
double spread_over(const std::vector<double>& time, const std::vector<double>& values, double from,
                   double to) {
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::size_t r = 0; r < time.size(); ++r)
    if (time[r] >= from && time[r] <= to) sum += values[r], sum2 += values[r] * values[r], ++n;
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
}

// The draft D_m = level - bottom averaged over the last `window` seconds: level from the
// water-height probes away from the box (interpolated to the body's rows), bottom = X - H/2.
Settled settle(const std::string& scene, int dim, double d0, double end_time, double window) {
  char name[64];
  std::snprintf(name, sizeof name, "floating_%dd_%g", dim, d0);
  const cli::RunOutcome outcome = testing::run_scene(scene, name,
                                                     {{"d0", std::to_string(d0)},
                                                      {"end_time", std::to_string(end_time)},
                                                      {"output_interval", "0.5"}});
  io::RunFileReader file(outcome.h5_path);
  const auto time = file.read_doubles("/bodies/box/time");
  const auto angle = file.read_doubles("/bodies/box/angle");
  std::vector<std::string> probes = dim == 2 ? std::vector<std::string>{"level_left", "level_right"}
                                             : std::vector<std::string>{"level"};
  const auto drafts = testing::box_draft(file, probes, dim - 1, 0.05);
  Settled s;
  s.draft = testing::mean_since(time, drafts, end_time - window);
  for (std::size_t r = 0; r < time.size(); ++r)
    if (time[r] >= end_time - window) s.angle = std::max(s.angle, std::abs(angle[r]));
  // The heave: the box's own height. The draft also carries the tank's sloshing at the probe,
  // which in 3D with the gradient scale outlasts the heave (draft spread ratio 1.03 at d0 =
  // 0.01 m over 2 s while the box's height fell to 0.79).
  const auto position = file.read_doubles("/bodies/box/position");
  std::vector<double> height(time.size());
  for (std::size_t r = 0; r < time.size(); ++r) height[r] = position[3 * r + dim - 1];
  s.spread = spread_over(time, height, end_time - 1.0, end_time);
  s.first_spread = spread_over(time, height, 0.0, 1.0);
  return s;
}

// Bounds: upright, roll below 0.05 rad; settling: the heave decays, the standard deviation of
// the box's height over the last second below decay_bound of that over the first. The tanks are
// closed and only 0.2 m (2D) or 0.1 m (3D) wider than the box on each side, so the waves the heave
// radiates come back within a period and the heave decays slowly (3D over 2 s: 0.72 at d0 =
// 0.02 m and 0.79 at 0.01 m with the gradient scale, 0.58 at 0.02 m without). An undamped
// coupling would keep the ratio near 1, an unstable one above it. The draft: within draft_bound
// of D.
void expect_settled(const std::string& scene, int dim, double d0, double end_time, double window,
                    double decay_bound, double draft_bound) {
  const double D = 0.05;
  const Settled s = settle(scene, dim, d0, end_time, window);
  std::printf(
      "%dD, d0 = %.4f m, %.0f s: draft over the last %.0f s %.5f m against D = %.4f m: error "
      "%+.2f %% (bound %.1f %%), the box's height spread %.4f m in the first second, "
      "%.4f m in the last (ratio %.2f, bound %.2f), largest roll %.3f rad\n",
      dim, d0, end_time, window, s.draft, D, 100 * (s.draft / D - 1), 100 * draft_bound / D,
      s.first_spread, s.spread, s.spread / s.first_spread, decay_bound, s.angle);
  EXPECT_LT(std::abs(s.draft - D), draft_bound);
  EXPECT_LT(s.spread, decay_bound * s.first_spread);
  EXPECT_LT(s.angle, 0.05);
}

// 2D: ten seconds, by when the heave has died down to a millimetre, and the mean over the last
// two against the accuracy issue's target, 2 % of D. Measured +0.24 % and +0.20 % with the
// pressure gradient normalised by each particle's neighbours (height spread ratios 0.03 and 0.02;
// +0.60 % and +0.55 % in the forty-sixth session, ratios 0.02 and 0.02);
// +2.9 % at d0 = 0.01 m with the lattice normalisation alone, where the settled water's pressure
// was 3 % low (docs/method.md, seventeenth session). (The time mean of the first three seconds
// depends on the heave's phase in the window: 1.3 % and 4.8 % over 0.5-1.5 s.)
TEST(FloatingBoxLong, SettlesAtTheArchimedesDraft2D) {
  for (double d0 : {0.01, 0.005})
    expect_settled("floating_box_2d.lua", 2, d0, 10.0, 2.0, 0.7, 0.02 * 0.05);
}

TEST(FloatingBoxLong, SettlesAtTheArchimedesDraft3D) {
  // 3D: 0.85, which still tells a decaying heave from an undamped one (near 1). The draft:
  // within one particle spacing, the mean of the last second of a heave still under way
  // (measured -0.66 % at d0 = 0.02 m and -2.9 % at 0.01 m; -1.3 % at 0.02 m with the lattice
  // normalisation alone; -2.6 % at 0.01 m in the fifteenth session).
  for (double d0 : {0.02, 0.01}) expect_settled("floating_box_3d.lua", 3, d0, 2.0, 1.0, 0.85, d0);
}

}  // namespace
}  // namespace washout
