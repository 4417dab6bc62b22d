#pragma once
// Advancing all rigid bodies over one fluid step with the fluid loads held constant, in as many
// contact sub-steps as the contact stiffness needs (METHOD.md Contact: "Sub-step the
// rigid/contact update inside each fluid step as needed, and report the number of sub-steps").
#include <span>
#include <vector>

#include "engine/contact/contact_forces.hpp"
#include "engine/rigid/body_load.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/body_state.hpp"
#include "engine/rigid/newton_euler.hpp"

namespace washout::contact {

struct SubstepReport {
  long substeps = 0;           // 1 when nothing touched or came near: no sub-stepping
  double smallest_step = 0.0;  // [s]
  int most_touching = 0;       // most particle contacts of one body at one sub-step
  std::vector<rigid::BodyLoad> contact_load;  // per body, time average over the fluid step
};

// The sub-step rule. Every sub-step finds the contacts and near contacts (particles that could
// touch before the fluid step ends, at their current speed and acceleration bounds) and bounds
// the highest angular frequency of each body's contacts,
//   omega^2 <= sum over contacts k_i (1/M + (r_i x n_i) . I^-1 (r_i x n_i)),
// with k_i = max(k_n, k_s) (linearised for Hertz). N particles pressing on a flat wall give
// about N k / M: the stiffness of the whole contact grows with the touching particles.
// Then t_contact = pi / omega and h = t_contact / steps_per_contact, shortened so that the
// sub-steps divide the rest of the fluid step evenly. With no contact in reach, one step.
// Throws std::runtime_error past settings.max_substeps.
SubstepReport advance_bodies(std::span<const rigid::BodyModel> models,
                             std::span<rigid::BodyState> states,
                             std::span<const rigid::BodyLoad> fluid_loads,
                             const ContactScene& scene, ContactWorkspace& workspace,
                             const Vec3& gravity, double t, double dt_fluid,
                             const rigid::IntegratorOptions& options = {});

}  // namespace washout::contact
