#include "engine/contact/contact_material.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace washout::contact {

int MaterialTable::add(const Material& material) {
  if (!(material.young_modulus > 0.0) || !(material.poisson_ratio > -1.0) ||
      !(material.poisson_ratio < 0.5) || !(material.restitution > 0.0) ||
      !(material.restitution <= 1.0))
    throw std::invalid_argument("contact material '" + material.name +
                                "': need E > 0, -1 < nu < 0.5, 0 < eps <= 1");
  materials_.push_back(material);
  grow();
  return size() - 1;
}

int MaterialTable::find(const std::string& name) const {
  for (int id = 0; id < size(); ++id)
    if (materials_[id].name == name) return id;
  return -1;
}

void MaterialTable::grow() {
  const int n = size(), old = n - 1;
  std::vector<double> friction(n * n, 0.0), restitution(n * n, -1.0);
  for (int a = 0; a < old; ++a) {
    for (int b = 0; b < old; ++b) {
      friction[a * n + b] = friction_[a * old + b];
      restitution[a * n + b] = restitution_[a * old + b];
    }
  }
  friction_.swap(friction);
  restitution_.swap(restitution);
}

int MaterialTable::index(int a, int b) const {
  if (a < 0 || b < 0 || a >= size() || b >= size())
    throw std::out_of_range("contact material id out of range");
  return a * size() + b;
}

void MaterialTable::set_friction(int a, int b, double mu) {
  if (!(mu >= 0.0)) throw std::invalid_argument("friction coefficient must be >= 0");
  friction_[index(a, b)] = mu;
  friction_[index(b, a)] = mu;
}

void MaterialTable::set_restitution(int a, int b, double eps) {
  if (!(eps > 0.0) || !(eps <= 1.0)) throw std::invalid_argument("restitution must be in (0,1]");
  restitution_[index(a, b)] = eps;
  restitution_[index(b, a)] = eps;
}

double MaterialTable::friction(int a, int b) const { return friction_[index(a, b)]; }

double MaterialTable::restitution(int a, int b) const {
  const double set = restitution_[index(a, b)];
  if (set > 0.0) return set;
  return std::sqrt(materials_[a].restitution * materials_[b].restitution);
}

// Hertz effective modulus and normal stiffness, METHOD.md Contact.
double normal_stiffness(double radius, const Material& i, const Material& j) {
  const double ei = i.young_modulus, ej = j.young_modulus;
  const double ni = i.poisson_ratio, nj = j.poisson_ratio;
  return (4.0 / 3.0) * std::sqrt(radius) * ei * ej / ((1.0 - ni * ni) * ej + (1.0 - nj * nj) * ei);
}

// Tangential stiffness, METHOD.md Contact.
double tangential_stiffness(double radius, const Material& i, const Material& j) {
  const double ei = i.young_modulus, ej = j.young_modulus;
  const double ni = i.poisson_ratio, nj = j.poisson_ratio;
  return 8.0 * std::sqrt(radius) * ei * ej /
         (2.0 * (2.0 - ni) * (1.0 + ni) * ej + 2.0 * (2.0 - nj) * (1.0 + nj) * ei);
}

// Normal damping from restitution, METHOD.md Contact.
double normal_damping(double restitution, double mass, double stiffness) {
  const double log_eps = std::log(restitution);
  return -2.0 * log_eps * std::sqrt(mass * stiffness) /
         std::sqrt(std::numbers::pi * std::numbers::pi + log_eps * log_eps);
}

double damping_ratio(double restitution) {
  const double log_eps = std::log(restitution);
  return -log_eps / std::sqrt(std::numbers::pi * std::numbers::pi + log_eps * log_eps);
}

double linear_restitution(double zeta) {
  if (zeta >= 1.0) return 0.0;
  return std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
}

}  // namespace washout::contact
