// A box resting on a floor: no drift and no jitter over 2 s, the contact force balancing M g;
// the sub-step counts for the paper's PLA girder; no sub-steps away from contact.
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

constexpr double kG = 9.81;

struct Rest {
  BodyModel model;
  ContactScene scene;
  Vec3 up;
  double touching_height = 0.0;  // X.up when the lowest particles just touch
};

Rest box_on_floor(int dim, const Vec3& size, double d0, double young_modulus) {
  Rest r;
  r.up = dim == 3 ? Vec3::UnitZ() : Vec3::UnitY();
  r.model = rigid::make_body_model(rigid::lattice_box(dim, d0, -0.5 * size, 0.5 * size, 1161.0));
  const int pla = r.scene.materials.add({"pla", young_modulus, 0.28, 0.8});
  r.scene.materials.set_friction(pla, pla, 0.3);
  r.scene.walls.push_back({"floor", PlaneWall{Vec3::Zero(), r.up}, pla});
  r.model.material = pla;
  r.touching_height = 0.5 * size.dot(r.up);  // the box's face is at X - size/2
  return r;
}

// 2 s at rest, fluid steps of 1 ms, after 0.5 s of settling from first touch (the contact's
// oscillation decays as exp(-zeta omega t), 1/(zeta omega) = 3 ms here in both 2D and 3D, so
// 0.5 s leaves nothing of it). Then the box must sit still at the static overlap Mg/(N k_n):
//  - position within 1e-6 of that overlap (rounding only: the linear law's equilibrium is
//    exact) and no horizontal drift (1e-12 m), no rotation (1e-10 rad);
//  - speed below 1e-9 m/s and spin below 1e-8 rad/s (no jitter);
//  - the mean contact force over each step equal to M g within 1e-9 relative.
// The test material is soft (E = 1e6 Pa in 3D; 1e8 Pa in 2D, where the mass per metre of
// thickness is 20 times larger) only to keep the test fast; the rule is the same.
void expect_rest(int dim) {
  Rest r = box_on_floor(dim, Vec3(0.1, dim == 3 ? 0.05 : 0.02, dim == 3 ? 0.02 : 0.0), 0.005,
                        dim == 3 ? 1e6 : 1e8);
  std::vector<BodyModel> models{r.model};
  std::vector<BodyState> states{rigid::initial_state(r.model)};
  states[0].position = r.touching_height * r.up;
  std::vector<rigid::BodyLoad> fluid(1);
  ContactWorkspace workspace;
  const double dt = 1e-3;
  double max_offset = 0, max_speed = 0, max_spin = 0, max_force_error = 0, max_drift = 0,
         max_angle = 0;
  long substeps = 0;
  int touching = 0;
  const double weight = r.model.mass * kG;
  for (int n = 0; n < 2500; ++n) {
    const SubstepReport report =
        advance_bodies(models, states, fluid, r.scene, workspace, -kG * r.up, n * dt, dt);
    if (n < 500) continue;
    const BodyState& s = states[0];
    touching = report.most_touching;
    substeps = std::max(substeps, report.substeps);
    const double k = workspace.wall_law[0].normal_stiffness;
    const double overlap = weight / (touching * k);
    max_offset = std::max(max_offset,
                          std::abs(r.touching_height - s.position.dot(r.up) - overlap) / overlap);
    max_drift = std::max(max_drift, (s.position - s.position.dot(r.up) * r.up).norm());
    max_angle = std::max(max_angle, Eigen::AngleAxisd(s.orientation).angle());
    max_speed = std::max(max_speed, s.velocity.norm());
    max_spin = std::max(max_spin, s.angular_velocity.norm());
    max_force_error =
        std::max(max_force_error, (report.contact_load[0].force - weight * r.up).norm() / weight);
  }
  std::printf(
      "%dD box at rest, %d particles touching, %ld sub-steps per 1 ms: overlap error "
      "%.1e, drift %.1e m, rotation %.1e rad, speed %.1e m/s, spin %.1e rad/s, "
      "|F_c - Mg|/Mg %.1e\n",
      dim, touching, substeps, max_offset, max_drift, max_angle, max_speed, max_spin,
      max_force_error);
  EXPECT_EQ(touching, dim == 3 ? 200 : 20);
  EXPECT_LT(max_offset, 1e-6);
  EXPECT_LT(max_drift, 1e-12);
  EXPECT_LT(max_angle, 1e-10);
  EXPECT_LT(max_speed, 1e-9);
  EXPECT_LT(max_spin, 1e-8);
  EXPECT_LT(max_force_error, 1e-9);
}

TEST(ContactResting, BoxStaysAtRest3D) { expect_rest(3); }
TEST(ContactResting, BoxStaysAtRest2D) { expect_rest(2); }

// The paper's girder: PLA (rho 1161, E = 5e9 Pa, nu = 0.28, eps = 0.8), 0.3 x 0.03 x 0.02 m at
// d0 = 5 mm (M = 0.209 kg), fluid step 0.5 ms, lying on a floor (360 particles touching) and
// on a 5 cm wide pier top (60 touching). Prints the sub-step counts; checks the force balance
// after the first touch has settled (2 fluid steps: the oscillation decays as exp(-zeta omega t)
// with 1/(zeta omega) < 0.1 ms) to 1e-7: the static overlap (~1e-10 m) is resolved against
// X ~ 1e-2 m only to ~1e-8 relative in double precision, which sets the noise floor. And that
// the count follows the rule: the sub-step is at most t_contact/20 for the bound
// omega^2 = sum k (1/M + (r x n).I^-1(r x n)) >= N k_s / M.
TEST(ContactResting, PaperGirderSubsteps) {
  const Vec3 size(0.3, 0.03, 0.02);
  Rest r = box_on_floor(3, size, 0.005, 5e9);
  r.scene.materials.set_friction(0, 0, 0.05);
  std::vector<rigid::BodyLoad> fluid(1);
  const double dt = 5e-4;
  const double weight = r.model.mass * kG;
  for (int on_pier = 0; on_pier < 2; ++on_pier) {
    ContactScene scene = r.scene;
    if (on_pier) {
      BoxObstacle pier;
      pier.centre = Vec3(0, 0, -0.5);
      pier.half_size = Vec3(0.025, 0.1, 0.5);
      scene.walls[0].shape = pier;
    }
    std::vector<BodyModel> models{r.model};
    std::vector<BodyState> states{rigid::initial_state(r.model)};
    states[0].position = r.touching_height * r.up;
    ContactWorkspace workspace;
    long most = 0, least = 1L << 40;
    int touching = 0;
    double force_error = 0;
    for (int n = 0; n < 5; ++n) {
      const SubstepReport report =
          advance_bodies(models, states, fluid, scene, workspace, -kG * r.up, n * dt, dt);
      most = std::max(most, report.substeps);
      least = std::min(least, report.substeps);
      touching = report.most_touching;
      if (n >= 2)
        force_error =
            std::max(force_error, (report.contact_load[0].force - weight * r.up).norm() / weight);
    }
    const double k_s = workspace.wall_law[0].tangential_stiffness;
    const double lowest =
        20.0 * dt / (std::numbers::pi * std::sqrt(r.model.mass / (touching * k_s)));
    std::printf(
        "PLA girder (M = %.4f kg) on %s: %d particles touching, %ld-%ld sub-steps per "
        "0.5 ms fluid step (sub-step %.2e s; N k_s/M alone would give %.0f); "
        "|F_c - Mg|/Mg %.1e\n",
        r.model.mass, on_pier ? "a 5 cm pier" : "the floor", touching, least, most, dt / most,
        lowest, force_error);
    EXPECT_EQ(touching, on_pier ? 60 : 360);
    EXPECT_GE(static_cast<double>(least), lowest);
    EXPECT_LT(force_error, 1e-7);
  }
}

// Nothing within reach: one step, bit-identical to a plain Newton-Euler step.
TEST(ContactResting, NoSubstepsAwayFromContact) {
  Rest r = box_on_floor(3, Vec3(0.1, 0.05, 0.02), 0.005, 5e9);
  std::vector<BodyModel> models{r.model};
  std::vector<BodyState> states{rigid::initial_state(r.model)};
  states[0].position = 0.1 * r.up;
  states[0].velocity = Vec3(0.3, 0.0, -1.0);
  states[0].angular_velocity = Vec3(1.0, 2.0, 0.5);
  BodyState alone = states[0];
  std::vector<rigid::BodyLoad> fluid(1);
  fluid[0].force = Vec3(0.1, 0.2, 0.3);
  ContactWorkspace workspace;
  const SubstepReport report =
      advance_bodies(models, states, fluid, r.scene, workspace, -kG * r.up, 0.0, 5e-4);
  rigid::advance_body(r.model, alone, fluid[0], -kG * r.up, 0.0, 5e-4);
  EXPECT_EQ(report.substeps, 1);
  EXPECT_EQ(states[0].position, alone.position);
  EXPECT_EQ(states[0].orientation.coeffs(), alone.orientation.coeffs());
  EXPECT_EQ(report.contact_load[0].force.norm(), 0.0);
}

}  // namespace
}  // namespace washout::contact
