// The fluid kept in cell order in memory (reorder_interval, engine/core/particle_order.hpp)
// changes where particles sit in the arrays, not the flow: a 2D dam break sorted every step and
// one never sorted write the same frames, particle by particle (the frames list them by id), to
// the round-off of sums taken in another order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

bool has_stage(const cli::RunOutcome& out, const std::string& name) {
  for (const auto& [stage, seconds] : out.summary.stage_seconds)
    if (stage == name) return true;
  return false;
}

TEST(FluidOrder, SortingTheFluidEveryStepLeavesTheFlowAsItWas) {
  const lua::Overrides common = {{"d0", "0.0146"}, {"end_time", "0.15"}};
  auto with = [&](const char* interval) {
    lua::Overrides o = common;
    o.push_back({"reorder_interval", interval});
    return o;
  };
  const auto kept = testing::run_scene("dambreak_2d.lua", "fluid_order_kept", with("0"));
  const auto sorted = testing::run_scene("dambreak_2d.lua", "fluid_order_sorted", with("1"));
  ASSERT_EQ(kept.exit_code, 0);
  ASSERT_EQ(sorted.exit_code, 0);
  EXPECT_FALSE(has_stage(kept, "reorder"));
  EXPECT_TRUE(has_stage(sorted, "reorder"));
  EXPECT_EQ(kept.summary.steps, sorted.summary.steps);

  io::RunFileReader a(kept.h5_path), b(sorted.h5_path);
  ASSERT_EQ(a.frame_count(), b.frame_count());
  double largest = 0.0;  // the largest distance between a particle's two places [m]
  for (std::size_t k = 0; k < a.frame_count(); ++k) {
    const io::FrameData x = a.read_frame(k), y = b.read_frame(k);
    ASSERT_EQ(x.count, y.count);
    // Rows are ids in both: 0, 1, 2, ...; the kinds (fluid first, walls after) agree.
    for (std::size_t i = 0; i < y.count; ++i) ASSERT_EQ(y.id[i], i);
    EXPECT_EQ(x.kind, y.kind);
    double frame_largest = 0.0;
    for (std::size_t i = 0; i < x.count; ++i) {
      double d2 = 0.0;
      for (int c = 0; c < x.dim; ++c)
        d2 += std::pow(x.position[i * x.dim + c] - y.position[i * y.dim + c], 2);
      frame_largest = std::max(frame_largest, std::sqrt(d2));
    }
    if (k == 0) {
      EXPECT_EQ(frame_largest, 0.0);  // the state as built
    }
    largest = std::max(largest, frame_largest);
  }
  // Round-off grown over the run's steps (measured 4e-16 m), far below a spacing (0.0146 m).
  EXPECT_LT(largest, 1e-9);
  const auto fa = a.read_doubles("/probes/front/value"), fb = b.read_doubles("/probes/front/value");
  ASSERT_EQ(fa.size(), fb.size());
  double front = 0.0;
  for (std::size_t k = 0; k < fa.size(); ++k) front = std::max(front, std::abs(fa[k] - fb[k]));
  EXPECT_LT(front, 1e-9);
  std::printf(
      "sorted every step against never: %ld steps, %zu frames, largest position difference "
      "%.2e m, front %.2e m\n",
      sorted.summary.steps, a.frame_count(), largest, front);
}

}  // namespace
}  // namespace washout
