#include "engine/contact/dem_contact.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/hertz_damping.hpp"

namespace washout::contact {

PairLaw make_pair_law(const ContactSettings& settings, double radius, const Material& a,
                      const Material& b, double friction, double restitution) {
  PairLaw law;
  law.law = settings.law;
  law.normal_stiffness = normal_stiffness(radius, a, b);
  law.tangential_stiffness = tangential_stiffness(radius, a, b);
  law.friction = friction;
  law.allow_tension = settings.allow_tension;
  if (settings.law == ContactLaw::kLinear) {
    // c_n = -2 ln(eps) sqrt(M k_n) / sqrt(pi^2 + ln(eps)^2) = 2 zeta sqrt(M k_n), METHOD.md.
    law.damping_factor = 2.0 * damping_ratio(restitution);
  } else {
    law.damping_factor = hertz_damping_factor(restitution);
  }
  return law;
}

namespace {

// Both stiffnesses of one contact, linearised at overlap max(delta, reference) for Hertz, the
// tangential one whatever the friction.
StepStiffness linearised_stiffnesses(const PairLaw& law, double overlap, double reference_overlap) {
  if (law.law == ContactLaw::kLinear) return {law.normal_stiffness, law.tangential_stiffness};
  const double root = std::sqrt(std::max(overlap, reference_overlap));
  // d/d(delta) of k_n delta^{3/2} is 1.5 k_n sqrt(delta); the tangential one is k_s sqrt(delta).
  return {1.5 * law.normal_stiffness * root, law.tangential_stiffness * root};
}

}  // namespace

double step_stiffness(const PairLaw& law, double overlap, double reference_overlap) {
  const StepStiffness k = linearised_stiffnesses(law, overlap, reference_overlap);
  return std::max(k.normal, k.tangential);
}

StepStiffness step_stiffnesses(const PairLaw& law, double overlap, double reference_overlap) {
  StepStiffness k = linearised_stiffnesses(law, overlap, reference_overlap);
  if (!(law.friction > 0.0)) k.tangential = 0.0;
  return k;
}

// DEM spring-dashpot contact, METHOD.md Contact:
//   F_n = -(k_n delta_n + c_n d(delta_n)/dt) n       (n there points into the partner)
//   F_s = -min(mu |F_n|, |k_s delta_s + c_s d(delta_s)/dt|) s_hat,   c_s = c_n
Vec3 spring_dashpot_force(const PairLaw& law, const ContactKinematics& c, double dt, Vec3& spring) {
  return spring_dashpot_force(law, c, dashpot_coefficient(law, c.damping_mass), dt, spring);
}

Vec3 spring_dashpot_force(const PairLaw& law, const ContactKinematics& c, double dashpot, double dt,
                          Vec3& spring) {
  const bool hertz = law.law == ContactLaw::kHertz;
  const double power = hertz ? 1.5 : 1.0;  // spring force ~ delta^power

  // The part of the step in contact (fraction), the overlap there, and the mean of delta^p
  // over it (left-point value for a whole step, as the explicit scheme uses).
  const double start = c.overlap, end = c.overlap + dt * c.overlap_rate;
  double fraction = 1.0, delta = start, spring_mean;
  // x^1 is x: the linear law (the default) skips pow, whose value for an exponent of 1 is x
  // itself (the README wash-out's girder.csv is the same to the bit), at 554 sub-steps a step.
  const auto spring_power = [&](double x) { return hertz ? std::pow(x, power) : x; };
  if (start > 0.0 && end > 0.0) {
    spring_mean = spring_power(start);
  } else if (start > 0.0 || end > 0.0) {
    const double peak = std::max(start, end);  // the overlap at the in-contact end
    fraction = peak / std::abs(end - start);
    delta = 0.5 * peak;
    spring_mean = spring_power(peak) / (power + 1.0);
  } else {
    spring.setZero();
    return Vec3::Zero();
  }

  const double damping = dashpot * (hertz ? std::sqrt(std::sqrt(delta)) : 1.0);
  double normal_force = law.normal_stiffness * spring_mean + damping * c.overlap_rate;
  if (!law.allow_tension) normal_force = std::max(normal_force, 0.0);

  // Tangential spring: keep its length, turn it onto the current tangent plane. (Already in
  // it, as on a flat face, where the turn would scale it by exactly 1: the roots are skipped.)
  const double along = spring.dot(c.normal);
  if (along != 0.0) {
    const double length = spring.norm();
    spring -= along * c.normal;
    const double projected = spring.norm();
    if (projected > 0.0) spring *= length / projected;
  }

  const double k_s = law.tangential_stiffness * (hertz ? std::sqrt(delta) : 1.0);
  Vec3 tangential = -k_s * spring - damping * c.tangential_velocity;
  const double limit = law.friction * std::max(normal_force, 0.0);
  // |F_s| > limit decided on the squares where they leave no doubt (the margin covers the
  // rounding of limit^2), with the root only near the limit and for the cap.
  const double magnitude2 = tangential.squaredNorm();
  if (magnitude2 > limit * limit * (1.0 - 1e-12) && std::sqrt(magnitude2) > limit) {
    // slip: the Coulomb slider caps the force and the spring
    const double magnitude = std::sqrt(magnitude2);
    tangential = magnitude > 0.0 ? Vec3(tangential * (limit / magnitude)) : Vec3::Zero();
    spring = k_s > 0.0 ? Vec3(-tangential / k_s) : Vec3::Zero();
  }
  spring += fraction * dt * c.tangential_velocity;
  return fraction * (normal_force * c.normal + tangential);
}

}  // namespace washout::contact
