// The step is composed from what a scene uses (engine/sim/step_plan.hpp): a stage the scene does
// not need is not in the list, and the order of the stages is METHOD.md's.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "engine/sim/step_plan.hpp"

namespace washout {
namespace {

bool has(const std::vector<Stage>& plan, Stage s) {
  return std::find(plan.begin(), plan.end(), s) != plan.end();
}

std::string text(const std::vector<Stage>& plan) {
  std::string t;
  for (Stage s : plan) {
    if (!t.empty()) t += ' ';
    t += stage_name(s);
  }
  return t;
}

TEST(StepPlan, StillTankRunsOnlyTheFluidStages) {
  const auto plan = compose_step({});
  std::printf("still tank: %s\n", text(plan).c_str());
  EXPECT_EQ(
      text(plan),
      "neighbours density wall_markers predictor ppe_assembly ppe_solve corrector advect clock "
      "checks push_out");
}

// The fluid is sorted in memory before anything builds lists over it, never mid-step.
TEST(StepPlan, TheFluidIsSortedFirst) {
  SceneFeatures f;
  f.reorder = true;
  const auto plan = compose_step(f);
  ASSERT_GE(plan.size(), 2u);
  EXPECT_EQ(plan[0], Stage::reorder);
  EXPECT_EQ(plan[1], Stage::neighbours);
  EXPECT_EQ(std::count(plan.begin(), plan.end(), Stage::reorder), 1);
}

TEST(StepPlan, BodiesBringTheirStagesAndNothingElse) {
  SceneFeatures f;
  f.bodies = f.dynamic_wall = true;
  const auto plan = compose_step(f);
  std::printf("floating body: %s\n", text(plan).c_str());
  for (Stage s : {Stage::squeeze_film, Stage::wall_accelerations, Stage::body_loads, Stage::bodies})
    EXPECT_TRUE(has(plan, s)) << stage_name(s);
  for (Stage s : {Stage::turbulence, Stage::moving_walls, Stage::wall_positions, Stage::shifting,
                  Stage::probes, Stage::wall_shear, Stage::prescribed_bodies})
    EXPECT_FALSE(has(plan, s)) << stage_name(s);
  // Only a body with a prescribed motion brings the stage that sets its velocities.
  f.prescribed_bodies = true;
  EXPECT_TRUE(has(compose_step(f), Stage::prescribed_bodies));
}

// density_kick = "positions": the density term's pressure is solved after the PPE's and before
// the corrector (which takes both), and its velocity comes back out after the move, before
// shifting reads the velocity; without the option neither stage is there.
TEST(StepPlan, TheDensityKickIsSolvedBeforeTheCorrectorAndTakenOutAfterTheMove) {
  SceneFeatures f;
  f.shifting = f.surface_smoothing = f.surface_strain = true;
  EXPECT_FALSE(has(compose_step(f), Stage::density_pressure));
  EXPECT_FALSE(has(compose_step(f), Stage::density_kick));
  f.density_kick = true;
  const auto plan = compose_step(f);
  std::printf("density kick: %s\n", text(plan).c_str());
  const auto at = [&](Stage s) { return std::find(plan.begin(), plan.end(), s) - plan.begin(); };
  EXPECT_EQ(at(Stage::density_pressure), at(Stage::ppe_solve) + 1);
  EXPECT_LT(at(Stage::density_pressure), at(Stage::corrector));
  EXPECT_EQ(at(Stage::density_kick), at(Stage::advect) + 1);
  EXPECT_LT(at(Stage::density_kick), at(Stage::shifting));
}

TEST(StepPlan, LoadsAreTakenBeforeTheFluidMovesAndChecksAfterTheClock) {
  SceneFeatures f;
  f.bodies = f.moving_walls = f.shifting = f.turbulence = f.probes = f.wall_friction = true;
  f.surface_smoothing = f.surface_strain = f.gradient_scale = true;
  const auto plan = compose_step(f);
  std::printf("everything: %s\n", text(plan).c_str());
  const auto at = [&](Stage s) { return std::find(plan.begin(), plan.end(), s) - plan.begin(); };
  EXPECT_LT(at(Stage::density), at(Stage::gradient_scale));       // it needs the free surface
  EXPECT_LT(at(Stage::gradient_scale), at(Stage::ppe_assembly));  // the own term's pair factor
  EXPECT_LT(at(Stage::turbulence), at(Stage::predictor));
  EXPECT_LT(at(Stage::predictor), at(Stage::wall_shear));
  EXPECT_LT(at(Stage::moving_walls), at(Stage::ppe_assembly));  // u_wall at t + dt in the PPE
  EXPECT_LT(at(Stage::ppe_solve), at(Stage::body_loads));
  EXPECT_LT(at(Stage::body_loads), at(Stage::corrector));              // P^{n+1} belongs to x^n
  EXPECT_LT(at(Stage::corrector), at(Stage::surface_smoothing));       // velocities, then positions
  EXPECT_LT(at(Stage::surface_smoothing), at(Stage::surface_strain));  // the moving velocity
  EXPECT_LT(at(Stage::surface_strain), at(Stage::advect));             // at the old positions
  EXPECT_LT(at(Stage::advect), at(Stage::shifting));
  EXPECT_LT(at(Stage::bodies), at(Stage::clock));
  EXPECT_LT(at(Stage::clock), at(Stage::checks));
  EXPECT_EQ(plan.back(), Stage::probes);
  EXPECT_FALSE(has(plan, Stage::squeeze_film));  // only with the dynamic wall condition
}

}  // namespace
}  // namespace washout
