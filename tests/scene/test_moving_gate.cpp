// A gate lifted at free-fall speed releases a water column: the fluid may not pass the gate
// while it still covers the column's foot, and runs out after it has cleared.
#include <gtest/gtest.h>

#include <cmath>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

TEST(MovingGate, HoldsThenReleasesTheColumn) {
  cli::RunRequest r;
  r.scene_path = std::string(WASHOUT_SOURCE_DIR) + "/tests/data/gate.lua";
  r.out_dir = testing::output_dir("moving_gate");
  r.render_frames = false;
  const auto out = cli::run_scene(r);
  ASSERT_EQ(out.exit_code, 0) << out.error << out.summary.message;
  io::RunFileReader run(out.h5_path);
  const auto t = run.read_doubles("/probes/front/time");
  const auto x = run.read_doubles("/probes/front/value");
  // The gate bottom rises as g t^2/2: 0.5 mm at t = 0.01 s, less than a particle radius, so no
  // particle can have passed under it yet.
  double early = 0, late = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] <= 0.01) early = std::max(early, x[k]);
    late = std::max(late, x[k]);
  }
  std::printf(
      "front before the gate clears: %.4f m (gate face at 0.1 m); at t = 0.25 s: %.4f m; "
      "wall crossings %ld\n",
      early, late, out.summary.wall_crossings);
  // front = furthest particle + d0/2; particles settle against the gate by a small fraction of
  // d0 (0.2 mm measured): a tenth of d0 is allowed, a particle past the gate is not.
  EXPECT_LE(early, 0.1 + 0.1 * 0.01);
  EXPECT_GT(late, 0.25);  // released: the surge has run well past the gate
  // Known limitation (docs/method.md): while the gap under the rising gate is narrower than a
  // particle, the first particles squeeze through past the gate's corner and are counted as
  // crossings (1 measured). More than a few would mean the walls leak.
  EXPECT_LE(out.summary.wall_crossings, 3);
}

}  // namespace
}  // namespace washout
