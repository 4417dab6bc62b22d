// Bouncing on a floor (refdata README section 6): a body dropped from h0 rebounds to
// h1 = e^2 h0, so the measured restitution sqrt(h1/h0) (= rebound / impact speed) must match
// the eps that set the dashpot, for the linear spring-dashpot (e = exp(-pi zeta/sqrt(1-zeta^2)))
// and for the Hertz option, in 2D and 3D, for a single flat landing of many particles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "engine/contact/contact_substepper.hpp"
#include "engine/rigid/lattice_body.hpp"

namespace washout::contact {
namespace {

using rigid::BodyModel;
using rigid::BodyState;

constexpr double kG = 9.81, kH0 = 0.05;

struct BounceResult {
  double restitution = 0.0;
  long most_substeps = 0;
  int touching = 0;
};

struct Floor {
  ContactScene scene;
  Vec3 up;
};

Floor floor_for(BodyModel& model, const ContactSettings& settings, double eps,
                double young_modulus) {
  Floor f;
  f.up = model.dim == 3 ? Vec3::UnitZ() : Vec3::UnitY();
  f.scene.settings = settings;
  const int material = f.scene.materials.add({"body", young_modulus, 0.3, eps});
  f.scene.walls.push_back({"floor", PlaneWall{Vec3::Zero(), f.up}, material});
  model.material = material;
  return f;
}

// Height of X when the body's lowest particle touches the floor.
double touching_height(const BodyModel& model, const Vec3& up) {
  double depth = 0.0;
  for (std::size_t i = 0; i < model.particle_count(); ++i)
    depth = std::max(depth, -model.offset[i].dot(up));
  return depth + model.contact_radius;
}

// One impact without gravity: the body starts 0.5 mm above the floor moving down at 1 m/s;
// after the contact it moves freely, so restitution = rebound / impact speed exactly.
BounceResult impact(BodyModel model, const ContactSettings& settings, double eps,
                    double young_modulus) {
  Floor f = floor_for(model, settings, eps, young_modulus);
  std::vector<BodyModel> models{model};
  std::vector<BodyState> states{rigid::initial_state(model)};
  states[0].position = (touching_height(model, f.up) + 5e-4) * f.up;
  states[0].velocity = -1.0 * f.up;
  std::vector<rigid::BodyLoad> fluid(1);
  ContactWorkspace workspace;
  BounceResult result;
  const double dt = 1e-3;
  for (int n = 0; n < 20; ++n) {
    const SubstepReport report =
        advance_bodies(models, states, fluid, f.scene, workspace, Vec3::Zero(), n * dt, dt);
    result.most_substeps = std::max(result.most_substeps, report.substeps);
    result.touching = std::max(result.touching, report.most_touching);
    if (report.substeps == 1 && states[0].velocity.dot(f.up) > 0.0) break;  // free again
  }
  result.restitution = states[0].velocity.dot(f.up) / 1.0;
  return result;
}

BodyModel sphere(int dim) {
  return rigid::make_body_model(rigid::lattice_ball(dim, 0.005, Vec3::Zero(), 0.02, 1000.0));
}

// Error budget of the explicit sub-steps at n steps per contact (omega h <= pi/n): the dashpot
// evaluated at the start of each step over-damps by ~ pi zeta^2 omega h (first order), and the
// contact's end falls anywhere inside a step, a phase error ~ (omega h)^2 (second order).
double tolerance(double eps, double steps) {
  const double zeta = damping_ratio(eps), omega_h = std::numbers::pi / steps;
  return std::numbers::pi * zeta * zeta * omega_h + omega_h * omega_h;
}

// Linear spring-dashpot, default settings (20 steps per contact), sphere (3D) and disc (2D):
// measured restitution within the budget above, and at 80 steps per contact within that
// step's budget (0.5-1.7 %): the law converges to the analytic value. (Measured below 1 % at 80
// while the sub-step took the trace of the contact stiffness, whose largest mode it
// overestimated; with the bound of contact_stiffness.hpp eps = 0.3 measures 1.01 % in 2D and
// 1.05 % in 3D against 1.73 %.)
TEST(ContactBounce, RestitutionMatchesEpsIn2DAnd3D) {
  for (int dim : {2, 3}) {
    for (double eps : {0.3, 0.5, 0.8, 0.95}) {
      ContactSettings fine;
      fine.steps_per_contact = 80;
      const BounceResult r = impact(sphere(dim), ContactSettings{}, eps, 5e7);
      const BounceResult f = impact(sphere(dim), fine, eps, 5e7);
      std::printf(
          "%dD eps %.2f: measured %.4f (error %+.2e, budget %.1e; %ld sub-steps/ms, "
          "%d touching); at 80 steps/contact %.4f (error %+.2e)\n",
          dim, eps, r.restitution, r.restitution / eps - 1, tolerance(eps, 20), r.most_substeps,
          r.touching, f.restitution, f.restitution / eps - 1);
      EXPECT_NEAR(r.restitution / eps, 1.0, tolerance(eps, 20));
      EXPECT_NEAR(f.restitution / eps, 1.0, tolerance(eps, 80));
      EXPECT_GT(r.touching, 1);  // the lattice ball lands on a flat layer of particles
    }
  }
}

// A box landing flat on 200 particles at once. Shared damping mass (default): the whole
// contact has the damping ratio of eps, so the box bounces with eps (budget as above).
// METHOD.md's whole-body mass per particle contact: N contacts of stiffness k and damping
// 2 zeta sqrt(M k) have damping ratio sqrt(N) zeta, so e = exp(-pi sqrt(N) zeta/...): checked
// against that prediction within the same budget.
TEST(ContactBounce, FlatLandingOfManyParticles) {
  const BodyModel box = rigid::make_body_model(
      rigid::lattice_box(3, 0.005, Vec3(-0.05, -0.025, -0.01), Vec3(0.05, 0.025, 0.01), 1000.0));
  const double eps = 0.95;
  const BounceResult shared = impact(box, ContactSettings{}, eps, 5e7);
  ContactSettings whole;
  whole.damping_mass = DampingMass::kWholeBody;
  const BounceResult literal = impact(box, whole, eps, 5e7);
  const double predicted = linear_restitution(std::sqrt(literal.touching) * damping_ratio(eps));
  std::printf(
      "flat box on %d particles, eps %.2f: shared mass e = %.4f (error %+.2e); "
      "whole-body mass e = %.4f (predicted sqrt(N) zeta: %.4f)\n",
      shared.touching, eps, shared.restitution, shared.restitution / eps - 1, literal.restitution,
      predicted);
  EXPECT_EQ(shared.touching, 200);
  EXPECT_NEAR(shared.restitution / eps, 1.0, tolerance(eps, 20));
  EXPECT_NEAR(literal.restitution / predicted, 1.0, tolerance(0.5, 20));
}

// Hertz option: F = k delta^{3/2} with Tsuji damping; alpha(eps) makes the restitution eps
// whatever the impact speed (checked at 0.5 and 2 m/s): same budget as the linear law.
TEST(ContactBounce, HertzRestitutionIsIndependentOfSpeed) {
  ContactSettings hertz;
  hertz.law = ContactLaw::kHertz;
  for (double eps : {0.5, 0.8}) {
    for (double speed : {0.5, 2.0}) {
      BodyModel ball = sphere(3);
      Floor f = floor_for(ball, hertz, eps, 5e9);
      std::vector<BodyModel> models{ball};
      std::vector<BodyState> states{rigid::initial_state(ball)};
      states[0].position = (touching_height(ball, f.up) + 2e-4) * f.up;
      states[0].velocity = -speed * f.up;
      std::vector<rigid::BodyLoad> fluid(1);
      ContactWorkspace workspace;
      long substeps = 0;
      for (int n = 0; n < 20; ++n) {
        const SubstepReport report =
            advance_bodies(models, states, fluid, f.scene, workspace, Vec3::Zero(), n * 1e-3, 1e-3);
        substeps = std::max(substeps, report.substeps);
        if (report.substeps == 1 && states[0].velocity.z() > 0.0) break;
      }
      const double e = states[0].velocity.z() / speed;
      std::printf("Hertz, eps %.2f, impact %.1f m/s: measured %.4f (error %+.2e, %ld sub-steps)\n",
                  eps, speed, e, e / eps - 1, substeps);
      EXPECT_NEAR(e / eps, 1.0, tolerance(eps, 20));
    }
  }
}

// Without tension (F_n >= 0) the dashpot cannot pull at the end of the contact, so less is
// dissipated: the restitution is above eps (and below 1).
TEST(ContactBounce, NoTensionBouncesHigher) {
  ContactSettings no_tension;
  no_tension.allow_tension = false;
  const BounceResult r = impact(sphere(3), no_tension, 0.5, 5e7);
  std::printf("no tension, eps 0.50: measured %.4f\n", r.restitution);
  EXPECT_GT(r.restitution, 0.5 * (1 + tolerance(0.5, 20)));
  EXPECT_LT(r.restitution, 1.0);
}

// Dropped under gravity from h0 = 5 cm: successive apex heights h_k = e^{2k} h0 (refdata
// README section 6). Fluid steps of 0.1 ms keep the free-flight error (~dt/t_flight) at 1e-3;
// each bounce adds the contact budget of 2.7 % of e, so h_k may be off by 2k times it.
TEST(ContactBounce, ApexHeightsUnderGravity) {
  const double eps = 0.8;
  BodyModel ball = sphere(3);
  Floor f = floor_for(ball, ContactSettings{}, eps, 5e7);
  std::vector<BodyModel> models{ball};
  std::vector<BodyState> states{rigid::initial_state(ball)};
  const double lift = touching_height(ball, f.up);
  states[0].position = (kH0 + lift) * f.up;
  std::vector<rigid::BodyLoad> fluid(1);
  ContactWorkspace workspace;
  const double dt = 1e-4;
  std::vector<double> apex;
  double previous_speed = 0.0, highest = 0.0;
  for (int n = 0; n < 10000 && apex.size() < 3; ++n) {
    const SubstepReport report =
        advance_bodies(models, states, fluid, f.scene, workspace, -kG * f.up, n * dt, dt);
    const double speed = states[0].velocity.z(), height = states[0].position.z() - lift;
    if (report.most_touching == 0 && previous_speed > 0.0) highest = std::max(highest, height);
    if (previous_speed > 0.0 && speed <= 0.0 && report.most_touching == 0) {
      apex.push_back(highest);
      highest = 0.0;
    }
    previous_speed = speed;
  }
  ASSERT_EQ(apex.size(), 3u);
  for (int k = 1; k <= 3; ++k) {
    const double exact = std::pow(eps, 2 * k) * kH0;
    const double error = apex[k - 1] / exact - 1;
    std::printf("apex %d: %.5f m, analytic e^%d h0 = %.5f m, error %+.2e\n", k, apex[k - 1], 2 * k,
                exact, error);
    EXPECT_NEAR(error, 0.0, 2 * k * tolerance(eps, 20) + 1e-3);
  }
}

}  // namespace
}  // namespace washout::contact
