// Body-body contact: particle pairs from the grid match a brute-force search; a head-on
// collision conserves momentum and rebounds with eps (reduced mass); a glancing collision with
// friction conserves linear and angular momentum and does not create energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "engine/contact/contact_substepper.hpp"
#include "engine/contact/particle_pair_grid.hpp"
#include "engine/rigid/lattice_body.hpp"

namespace washout::contact {
namespace {

using rigid::BodyModel;
using rigid::BodyState;

TEST(ContactPairGrid, MatchesBruteForce) {
  for (int dim : {2, 3}) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-0.1, 0.1);
    rigid::Vec3Array x;
    std::vector<std::int32_t> group;
    for (int i = 0; i < 2000; ++i) {
      x.push_back(Vec3(uniform(random), uniform(random), dim == 3 ? uniform(random) : 0.0));
      group.push_back(i % 3);
    }
    const double cutoff = 0.012;
    ParticlePairGrid grid;
    std::vector<ParticlePair> pairs;
    grid.find_pairs(x, group, cutoff, dim, pairs);
    std::set<std::pair<int, int>> found, expected;
    for (const ParticlePair& p : pairs) found.insert({p.i, p.j});
    for (int i = 0; i < 2000; ++i)
      for (int j = i + 1; j < 2000; ++j)
        if (group[i] != group[j] && (x[i] - x[j]).norm() < cutoff) expected.insert({i, j});
    std::printf("%dD: %zu pairs from the grid, %zu by brute force\n", dim, found.size(),
                expected.size());
    EXPECT_EQ(found.size(), pairs.size());  // no duplicates
    EXPECT_EQ(found, expected);
  }
}

struct Collision {
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  ContactScene scene;
};

// Two cubes of side 4 cm (2D: squares), densities 1000 and 3000 (reduced mass 3/4 of the
// lighter), their facing sides on the same lattice rows, approaching at 1.5 m/s. E = 5e7 Pa.
Collision head_on(int dim, double eps, double mu) {
  Collision c;
  const int material = c.scene.materials.add({"cube", 5e7, 0.3, eps});
  c.scene.materials.set_friction(material, material, mu);
  const Vec3 half = dim == 3 ? Vec3(0.02, 0.02, 0.02) : Vec3(0.02, 0.02, 0.0);
  for (double density : {1000.0, 3000.0}) {
    BodyModel m = rigid::make_body_model(rigid::lattice_box(dim, 0.005, -half, half, density));
    m.material = material;
    c.models.push_back(m);
  }
  c.states.push_back(rigid::initial_state(c.models[0]));
  c.states.push_back(rigid::initial_state(c.models[1]));
  c.states[0].position = Vec3(-0.0205, 0, 0);  // faces 1 mm apart
  c.states[1].position = Vec3(0.0205, 0, 0);
  c.states[0].velocity = Vec3(1.0, 0, 0);
  c.states[1].velocity = Vec3(-0.5, 0, 0);
  return c;
}

struct Totals {
  Vec3 momentum = Vec3::Zero(), angular = Vec3::Zero();
  double energy = 0.0;
};

Totals totals(const Collision& c) {
  Totals t;
  for (std::size_t b = 0; b < c.models.size(); ++b) {
    const BodyModel& m = c.models[b];
    const BodyState& s = c.states[b];
    t.momentum += m.mass * s.velocity;
    t.angular += s.position.cross(m.mass * s.velocity) + rigid::angular_momentum(m, s);
    t.energy += rigid::kinetic_energy(m, s);
  }
  return t;
}

// Runs 1 ms fluid steps until the bodies separate; returns the most sub-steps in one.
long run(Collision& c, int max_steps) {
  std::vector<rigid::BodyLoad> fluid(c.models.size());
  ContactWorkspace workspace;
  long most = 0;
  bool touched = false;
  for (int n = 0; n < max_steps; ++n) {
    const SubstepReport report =
        advance_bodies(c.models, c.states, fluid, c.scene, workspace, Vec3::Zero(), n * 1e-3, 1e-3);
    most = std::max(most, report.substeps);
    if (report.most_touching > 0) touched = true;
    if (touched && report.substeps == 1) break;
  }
  return most;
}

// Head-on: momentum to rounding (1e-12 relative; forces are equal and opposite pair by pair);
// restitution (v_b' - v_a') / (v_a - v_b) = eps within the budget of the explicit sub-steps
// (pi zeta^2 omega h + (omega h)^2 at 20 steps per contact, as for the bouncing test).
TEST(ContactBodyBody, HeadOnCollisionConservesMomentumAndGivesEps) {
  for (int dim : {3, 2}) {
    for (double eps : {0.5, 0.8}) {
      Collision c = head_on(dim, eps, 0.0);
      const Totals before = totals(c);
      const double approach = c.states[0].velocity.x() - c.states[1].velocity.x();
      const long substeps = run(c, 20);
      const Totals after = totals(c);
      const double rebound = c.states[1].velocity.x() - c.states[0].velocity.x();
      const double momentum_error =
          (after.momentum - before.momentum).norm() / (c.models[0].mass * 1.0);
      const double zeta = damping_ratio(eps), omega_h = std::numbers::pi / 20;
      const double budget = std::numbers::pi * zeta * zeta * omega_h + omega_h * omega_h;
      std::printf(
          "%dD head-on, eps %.2f: restitution %.4f (error %+.2e, budget %.1e), "
          "momentum error %.1e, spin %.1e rad/s, %ld sub-steps/ms\n",
          dim, eps, rebound / approach, rebound / (approach * eps) - 1, budget, momentum_error,
          c.states[0].angular_velocity.norm(), substeps);
      EXPECT_LT(momentum_error, 1e-12);
      EXPECT_NEAR(rebound / (approach * eps), 1.0, budget);
      EXPECT_LT(c.states[0].angular_velocity.norm(), 1e-9);
    }
  }
}

// Glancing, with friction mu = 0.3 and spin: the bodies are offset across the motion and the
// first one spins, so the friction torques matter. Linear and angular momentum (about the
// origin) are conserved to rounding (1e-12); the kinetic energy does not grow.
TEST(ContactBodyBody, GlancingCollisionWithFrictionConservesMomenta) {
  for (int dim : {3, 2}) {
    Collision c = head_on(dim, 0.5, 0.3);
    c.states[0].position.y() = 0.015;
    c.states[0].velocity.y() = -0.3;
    c.states[0].angular_velocity = dim == 3 ? Vec3(3.0, -2.0, 20.0) : Vec3(0, 0, 20.0);
    const Totals before = totals(c);
    run(c, 40);
    const Totals after = totals(c);
    const double p_error = (after.momentum - before.momentum).norm() / before.momentum.norm();
    const double l_error = (after.angular - before.angular).norm() / before.angular.norm();
    std::printf(
        "%dD glancing, mu 0.3: momentum error %.1e, angular momentum error %.1e, "
        "energy %.4f -> %.4f J, spin of body 2 %.2f rad/s\n",
        dim, p_error, l_error, before.energy, after.energy, c.states[1].angular_velocity.norm());
    EXPECT_LT(p_error, 1e-12);
    EXPECT_LT(l_error, 1e-12);
    EXPECT_LT(after.energy, before.energy);
    EXPECT_GT(c.states[1].angular_velocity.norm(), 0.1);  // friction did act
  }
}

// A cube hitting a fixed body (a fixed body is infinitely heavy: the reduced mass is the cube's
// own) rebounds with eps, within the same budget; the fixed body does not move.
TEST(ContactBodyBody, BounceOffAFixedBody) {
  const double eps = 0.8;
  Collision c = head_on(3, eps, 0.0);
  c.models[1].motion = rigid::MotionKind::kFixed;
  c.states[1].velocity.setZero();
  const Vec3 fixed_at = c.states[1].position;
  run(c, 20);
  const double e = -c.states[0].velocity.x() / 1.0;
  const double zeta = damping_ratio(eps), omega_h = std::numbers::pi / 20;
  const double budget = std::numbers::pi * zeta * zeta * omega_h + omega_h * omega_h;
  std::printf("cube on a fixed body, eps %.2f: restitution %.4f (error %+.2e, budget %.1e)\n", eps,
              e, e / eps - 1, budget);
  EXPECT_NEAR(e / eps, 1.0, budget);
  EXPECT_EQ(c.states[1].position, fixed_at);
}

}  // namespace
}  // namespace washout::contact
