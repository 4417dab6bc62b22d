// Bodies at rest put to sleep (engine/contact/body_rest.hpp): a box dropped on a floor bounces,
// settles and then sleeps at its static overlap, never while it still moves; what counts as at
// rest, and what keeps the bodies awake.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "engine/contact/body_rest.hpp"
#include "engine/contact/contact_substepper.hpp"
#include "engine/rigid/lattice_body.hpp"

namespace washout::contact {
namespace {

using rigid::BodyLoad;
using rigid::BodyModel;
using rigid::BodyState;

constexpr double kG = 9.81;
const Vec3 kGravity(0, 0, -kG);

BodyModel pla_box() {
  return rigid::make_body_model(
      rigid::lattice_box(3, 0.005, Vec3(-0.05, -0.025, -0.01), Vec3(0.05, 0.025, 0.01), 1161.0));
}

// Dropped from 5 mm onto a floor (restitution 0.8: it bounces for about 0.3 s), fluid steps of
// 1 ms, no fluid anywhere. It must fall asleep once, within 2 s, after `steps` steps in which
// every point of it moved slower than kRestSpeed g dt, and sleep at the static overlap
// M g / (N k_n) (the linear law's equilibrium, exact up to rounding: 1e-6, as
// test_contact_resting.cpp bounds it).
TEST(BodyRest, DroppedBoxSleepsOnceSettledAtItsStaticOverlap) {
  BodyModel model = pla_box();
  ContactScene scene;
  const int pla = scene.materials.add({"pla", 1e6, 0.28, 0.8});
  scene.materials.set_friction(pla, pla, 0.3);
  scene.walls.push_back({"floor", PlaneWall{Vec3::Zero(), Vec3::UnitZ()}, pla});
  model.material = pla;
  std::vector<BodyModel> models{model};
  std::vector<BodyState> states{rigid::initial_state(model)};
  states[0].position = Vec3(0, 0, 0.01 + 0.005);  // the lowest particles' surface 5 mm up
  const std::vector<BodyLoad> fluid(1);
  ContactWorkspace workspace;
  const double dt = 1e-3;
  const int steps = 10;
  RestWatch watch(steps);
  std::vector<double> speed;  // per step: the fastest point of the box
  int asleep_at = -1, touching = 0, sleeps = 0;
  SubstepReport report;
  for (int n = 0; n < 2000; ++n) {
    // Asleep, the box is no longer advanced (as RigidBodySystem::advance does), and the watch,
    // still asked every step with the held loads, must not report a second falling asleep.
    if (!watch.asleep()) {
      report = advance_bodies(models, states, fluid, scene, workspace, kGravity, n * dt, dt);
      touching = report.most_touching;
      speed.push_back(states[0].velocity.norm() +
                      states[0].angular_velocity.norm() * model.bounding_radius);
    }
    if (watch.observe(models, states, fluid, report.contact_load, kGravity, dt, true)) {
      if (asleep_at < 0) asleep_at = n;
      ++sleeps;
    }
  }
  ASSERT_GE(asleep_at, 0) << "the box never fell asleep in 2 s";
  double fastest_before = 0.0;  // over the steps counted towards sleep
  for (int n = asleep_at - steps + 1; n <= asleep_at; ++n)
    fastest_before = std::max(fastest_before, speed[n]);
  double fastest_while_bouncing = 0.0;  // the steps before those
  for (int n = 0; n <= asleep_at - steps; ++n)
    fastest_while_bouncing = std::max(fastest_while_bouncing, speed[n]);
  const double k = workspace.wall_law[0].normal_stiffness;
  const double overlap = model.mass * kG / (touching * k);
  const double offset = std::abs(0.01 - states[0].position.z() - overlap) / overlap;
  std::printf(
      "asleep at t = %.3f s after %d still steps; fastest point over them %.1e m/s (bound "
      "%.1e), before them %.2f m/s; %d particles touching, overlap error %.1e\n",
      (asleep_at + 1) * dt, steps, fastest_before, kRestSpeed * kG * dt, fastest_while_bouncing,
      touching, offset);
  EXPECT_EQ(sleeps, 1);       // once, over the 2 s
  EXPECT_GT(asleep_at, 100);  // the bounces last about 0.3 s
  EXPECT_LT(fastest_before, kRestSpeed * kG * dt);
  EXPECT_GT(fastest_while_bouncing, 0.1);  // it did bounce: no sleep in the air
  EXPECT_EQ(touching, 200);
  EXPECT_LT(offset, 1e-6);
  EXPECT_TRUE(watch.asleep());
}

TEST(BodyRest, StillAndBalancedOnlyIsAtRest) {
  const BodyModel model = pla_box();
  BodyState still = rigid::initial_state(model);
  const double weight = model.mass * kG, dt = 1e-3;
  BodyLoad support;
  support.force = Vec3(0, 0, weight);
  BodyLoad none;
  EXPECT_TRUE(body_at_rest(model, still, none, support, kGravity, dt));
  // The top of a bounce: still for an instant, but nothing holds it up.
  EXPECT_FALSE(body_at_rest(model, still, none, none, kGravity, dt));
  // Held by the fluid as much as by the contact.
  BodyLoad half;
  half.force = Vec3(0, 0, 0.5 * weight);
  EXPECT_TRUE(body_at_rest(model, still, half, half, kGravity, dt));
  // A load off by more than kRestLoad of the weight, or a couple.
  BodyLoad short_support = support;
  short_support.force.z() *= 1 - 3 * kRestLoad;
  EXPECT_FALSE(body_at_rest(model, still, none, short_support, kGravity, dt));
  BodyLoad twisted = support;
  twisted.torque = Vec3(0, 3 * kRestLoad * weight * model.bounding_radius, 0);
  EXPECT_FALSE(body_at_rest(model, still, none, twisted, kGravity, dt));
  // Moving: a sliding box, a slowly turning one, one at half the bound, one that is not finite.
  const double bound = kRestSpeed * kG * dt;
  BodyState sliding = still;
  sliding.velocity = Vec3(2 * bound, 0, 0);
  EXPECT_FALSE(body_at_rest(model, sliding, none, support, kGravity, dt));
  BodyState turning = still;
  turning.angular_velocity = Vec3(0, 0, 2 * bound / model.bounding_radius);
  EXPECT_FALSE(body_at_rest(model, turning, none, support, kGravity, dt));
  BodyState creeping = still;
  creeping.velocity = Vec3(0.5 * bound, 0, 0);
  EXPECT_TRUE(body_at_rest(model, creeping, none, support, kGravity, dt));
  BodyState broken = still;
  broken.velocity.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(body_at_rest(model, broken, none, support, kGravity, dt));
  // Without gravity there is no scale: only an exactly still, unloaded body is at rest.
  EXPECT_TRUE(body_at_rest(model, still, none, none, Vec3::Zero(), dt));
  EXPECT_FALSE(body_at_rest(model, creeping, none, none, Vec3::Zero(), dt));
}

TEST(BodyRest, FluidNearAPrescribedBodyOrAWakeKeepsThemAwake) {
  const BodyModel model = pla_box();
  BodyModel pusher = model;
  pusher.motion = rigid::MotionKind::kPrescribed;
  BodyModel pier = model;
  pier.motion = rigid::MotionKind::kFixed;
  const BodyState still = rigid::initial_state(model);
  BodyLoad support;
  support.force = Vec3(0, 0, model.mass * kG);
  const double dt = 1e-3;
  const auto steps_to_sleep = [&](std::vector<BodyModel> models, RestWatch& watch, int wet_at) {
    const std::vector<BodyState> states(models.size(), still);
    const std::vector<BodyLoad> fluid(models.size()), contact(models.size(), support);
    for (int n = 0; n < 50; ++n)
      if (watch.observe(models, states, fluid, contact, kGravity, dt, n != wet_at)) return n + 1;
    return -1;
  };
  RestWatch watch(5);
  EXPECT_EQ(steps_to_sleep({model, pier}, watch, -1), 5);  // a fixed body moves nothing
  RestWatch wet(5);
  EXPECT_EQ(steps_to_sleep({model}, wet, 3), 9);  // fluid near at the 4th step: counted again
  RestWatch pushed(5);
  EXPECT_EQ(steps_to_sleep({model, pusher}, pushed, -1), -1);
  RestWatch none(5);
  EXPECT_EQ(steps_to_sleep({pier}, none, -1), -1);  // nothing to hold
  RestWatch off(0);
  EXPECT_EQ(steps_to_sleep({model}, off, -1), -1);  // rest_steps = 0: never
  // Woken, the count starts again; a restored count goes on from where it was.
  watch.wake();
  EXPECT_FALSE(watch.asleep());
  EXPECT_EQ(steps_to_sleep({model}, watch, -1), 5);
  RestWatch restored(5);
  restored.restore(3);
  EXPECT_EQ(steps_to_sleep({model}, restored, -1), 2);
}

}  // namespace
}  // namespace washout::contact
