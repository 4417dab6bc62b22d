// The body coupling's response solves (implicit_body_coupling.cpp): solved first to
// coupling_tolerance (relative to the largest response of their kind), and where their share of
// the coupled pressure's residual exceeds the pressure solve's tolerance, the coupled pressure is
// solved once more and its load corrects the bodies' velocities. That must not change the
// bodies' motion: the 3D floating box (pcg_agg, six responses) released out of equilibrium, with
// the responses first solved to 1e-2 (the default) and to 1e-8 (every response as tightly as the
// pressure): the paths must agree to 1e-7 m (measured: 8e-10 m over 0.2 s, the box moving
// 11 mm) while the loose run takes fewer solver iterations (measured 28.8 against 140.4 a step;
// 30.9 against 142.7 when the responses were solved again instead of the pressure).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

TEST(BodyCoupling, LooseResponsesMoveTheBodyAsTightOnes) {
  const auto run = [](const std::string& tolerance) {
    return testing::run_scene(
        "floating_box_3d.lua", "coupling_tolerance_" + tolerance,
        {{"end_time", "0.2"}, {"output_interval", "0.1"}, {"coupling_tolerance", tolerance}});
  };
  const cli::RunOutcome loose = run("1e-2"), tight = run("1e-8");
  const auto a = io::RunFileReader(loose.h5_path).read_doubles("/bodies/box/position");
  const auto b = io::RunFileReader(tight.h5_path).read_doubles("/bodies/box/position");
  ASSERT_EQ(a.size(), b.size());
  double largest = 0.0, heave = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) largest = std::max(largest, std::abs(a[k] - b[k]));
  for (std::size_t k = 2; k < b.size(); k += 3) heave = std::max(heave, std::abs(b[k] - b[2]));
  const double its_loose = loose.summary.mean_ppe_iterations;
  const double its_tight = tight.summary.mean_ppe_iterations;
  std::printf(
      "box moved %.4f m; largest position difference %.2e m; solver iterations a step %.1f "
      "(responses first to 1e-2) against %.1f (1e-8)\n",
      heave, largest, its_loose, its_tight);
  EXPECT_GT(heave, 1e-3) << "the box must move for the comparison to mean anything";
  EXPECT_LT(largest, 1e-7);
  EXPECT_LT(its_loose, its_tight);
}

}  // namespace
}  // namespace washout
