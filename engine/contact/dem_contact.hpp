#pragma once
// The DEM spring-dashpot law for one contact (METHOD.md Contact): a normal spring and dashpot,
// and a tangential spring and dashpot in series with a Coulomb slider. The sweeps that find
// contacts and sum forces on bodies are in contact_forces.hpp.
#include <cmath>
#include <cstdint>

#include "engine/contact/contact_material.hpp"
#include "engine/core/vec3.hpp"

namespace washout::contact {

enum class ContactLaw : std::uint8_t {
  kLinear,  // F_n = k_n delta + c_n d(delta)/dt (default; METHOD.md's k_n used as N/m)
  kHertz,   // F_n = k_n delta^{3/2} + alpha sqrt(m k_n) delta^{1/4} d(delta)/dt, tangential
            // spring k_s sqrt(delta) (Hertz-Mindlin); alpha from eps (hertz_damping.hpp)
};

// Which mass sets the dashpot of one particle contact.
enum class DampingMass : std::uint8_t {
  // M / N_c: a body touching a partner at N_c particles shares its mass among them, so the whole
  // contact (stiffness N_c k_n, damping N_c c_n) has the damping ratio that gives eps. Default.
  kShared,
  // M per particle contact, METHOD.md as written: with N_c touching particles the damping ratio
  // is sqrt(N_c) times too large (a flat face landing on a floor hardly bounces).
  kWholeBody,
};

struct ContactSettings {
  ContactLaw law = ContactLaw::kLinear;
  DampingMass damping_mass = DampingMass::kShared;
  // true: the normal force may pull at the end of a contact (the dashpot outweighs the spring),
  // as in the analytic linear spring-dashpot whose restitution METHOD.md's c_n formula inverts.
  // false: F_n >= 0 (no adhesion); the measured restitution is then above eps.
  bool allow_tension = true;
  double steps_per_contact = 20.0;  // dt_c = t_contact / steps_per_contact
  // Hertz only: the stiffness used for the step size is taken at an overlap of at least this
  // fraction of r, so that a contact about to start already limits the step.
  double hertz_reference_overlap = 0.01;
  long max_substeps = 1000000;  // per fluid step; more is reported as an error
};

// Constants of one pair of materials for one particle radius.
struct PairLaw {
  ContactLaw law = ContactLaw::kLinear;
  double normal_stiffness = 0.0;      // k_n: N/m (linear) or N/m^{3/2} (Hertz)
  double tangential_stiffness = 0.0;  // k_s: N/m (linear) or N/m^{3/2} (Hertz-Mindlin)
  double damping_factor = 0.0;        // c = damping_factor sqrt(m k_n) [delta^{1/4} for Hertz]
  double friction = 0.0;              // mu
  bool allow_tension = true;
};

PairLaw make_pair_law(const ContactSettings& settings, double radius, const Material& a,
                      const Material& b, double friction, double restitution);

// The largest stiffness (normal or tangential) of one contact, linearised at overlap
// max(delta, reference) for Hertz: what limits the explicit step.
double step_stiffness(const PairLaw& law, double overlap, double reference_overlap);

// The normal and the tangential stiffness of one contact, each linearised as above; the
// tangential one is 0 without friction, where the Coulomb cap holds the tangential force at 0.
struct StepStiffness {
  double normal = 0.0, tangential = 0.0;
};
StepStiffness step_stiffnesses(const PairLaw& law, double overlap, double reference_overlap);

// One contact at the start of a step. overlap delta (> 0 in contact; <= 0 for a near pair that
// may touch within the step); normal n points from the partner into this particle;
// overlap_rate = d(delta)/dt = -(u_rel . n); tangential_velocity = the tangential part of u_rel
// (u_rel = particle velocity minus the partner's); damping_mass = the mass that sets c_n.
struct ContactKinematics {
  double overlap = 0.0;
  double overlap_rate = 0.0;
  Vec3 normal = Vec3::Zero();
  Vec3 tangential_velocity = Vec3::Zero();
  double damping_mass = 0.0;
};

// True when the pair overlaps during some part of the step [t, t + dt], taking the overlap as
// linear in time over the step.
inline bool touches_during_step(double overlap, double overlap_rate, double dt) {
  return overlap > 0.0 || overlap + dt * overlap_rate > 0.0;
}

// The dashpot's coefficient before the Hertz factor, c = 2 zeta sqrt(m k_n) (METHOD.md): the
// same for every contact of one body with one partner in a sub-step, so the sub-steps compute
// it once per partner instead of once per contact.
inline double dashpot_coefficient(const PairLaw& law, double damping_mass) {
  return law.damping_factor * std::sqrt(damping_mass * law.normal_stiffness);
}

// Force on the particle from this contact over a step dt (zero when it does not touch during
// the step). `spring` is the tangential spring displacement delta_s kept for the pair across
// sub-steps (zero for a new contact): it is turned onto the current tangent plane, capped at the
// Coulomb limit when the contact slips, and advanced by u_t dt for the next step.
// A contact that starts or ends inside the step acts for that part of the step only, with its
// mean force there: the impulse is then right to second order, which keeps the restitution
// from depending on where the contact falls between sub-steps.
Vec3 spring_dashpot_force(const PairLaw& law, const ContactKinematics& contact, double dt,
                          Vec3& spring);
// The same with the dashpot's coefficient given (dashpot_coefficient(law, damping_mass)).
Vec3 spring_dashpot_force(const PairLaw& law, const ContactKinematics& contact, double dashpot,
                          double dt, Vec3& spring);

}  // namespace washout::contact
