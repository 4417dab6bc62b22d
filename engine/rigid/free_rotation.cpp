#include "engine/rigid/free_rotation.hpp"

#include <cmath>

namespace washout::rigid {
namespace {

// The body turns by phi = tau L_k / I_k about its principal axis k (a body-frame rotation, on
// the right of q); the principal components of the fixed world L turn by -phi about that axis.
void rotate_about_principal_axis(int k, double tau, const Vec3& moments, Eigen::Quaterniond& q,
                                 Vec3& momentum_principal) {
  const double phi = tau * momentum_principal[k] / moments[k];
  q = q * Eigen::Quaterniond(Eigen::AngleAxisd(phi, Vec3::Unit(k)));
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  const double c = std::cos(phi), s = std::sin(phi);
  const double la = momentum_principal[a], lb = momentum_principal[b];
  momentum_principal[a] = c * la + s * lb;
  momentum_principal[b] = -s * la + c * lb;
}

}  // namespace

Eigen::Quaterniond free_rotation(const BodyModel& model, const Eigen::Quaterniond& q,
                                 const Vec3& momentum, double dt) {
  const Eigen::Quaterniond principal_to_body(model.principal_axes);
  Eigen::Quaterniond q_principal = q * principal_to_body;  // principal frame -> world
  Vec3 l = q_principal.conjugate() * momentum;             // principal components of L
  const Vec3& moments = model.principal_moments;
  // Symmetric sequence 1(dt/2) 2(dt/2) 3(dt) 2(dt/2) 1(dt/2): second order and reversible.
  rotate_about_principal_axis(0, 0.5 * dt, moments, q_principal, l);
  rotate_about_principal_axis(1, 0.5 * dt, moments, q_principal, l);
  rotate_about_principal_axis(2, dt, moments, q_principal, l);
  rotate_about_principal_axis(1, 0.5 * dt, moments, q_principal, l);
  rotate_about_principal_axis(0, 0.5 * dt, moments, q_principal, l);
  return (q_principal * principal_to_body.conjugate()).normalized();
}

}  // namespace washout::rigid
