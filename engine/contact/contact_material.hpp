#pragma once
// Contact materials and the per-pair constants of the DEM spring-dashpot law
// (METHOD.md Contact): Hertz effective stiffnesses, damping from restitution, friction table.
#include <string>
#include <vector>

namespace washout::contact {

struct Material {
  std::string name;
  double young_modulus = 5.0e9;  // E [Pa] (the paper's 5.0e5 N/cm^2)
  double poisson_ratio = 0.28;   // nu [-]
  double restitution = 0.8;      // eps [-], used when a pair sets none
};

// Materials by id, with per-pair friction (default 0) and restitution (default: the geometric
// mean of the two materials' values, which is the value itself for a pair of one material).
class MaterialTable {
 public:
  int add(const Material& material);        // returns its id
  int find(const std::string& name) const;  // id, or -1
  const Material& material(int id) const { return materials_.at(id); }
  int size() const { return static_cast<int>(materials_.size()); }

  void set_friction(int a, int b, double mu);
  void set_restitution(int a, int b, double eps);
  double friction(int a, int b) const;
  double restitution(int a, int b) const;

 private:
  int index(int a, int b) const;  // into the pair vectors, symmetric in a and b
  void grow();
  std::vector<Material> materials_;
  std::vector<double> friction_;     // size()^2, symmetric
  std::vector<double> restitution_;  // size()^2, negative = not set
};

// Hertz effective normal stiffness, METHOD.md Contact:
//   k_n = (4/3) sqrt(r) E_i E_j / ((1 - nu_i^2) E_j + (1 - nu_j^2) E_i)     [N/m^{3/2}]
double normal_stiffness(double radius, const Material& i, const Material& j);

// Tangential stiffness, METHOD.md Contact:
//   k_s = 8 sqrt(r) E_i E_j / (2 (2 - nu_i)(1 + nu_i) E_j + 2 (2 - nu_j)(1 + nu_j) E_i)
double tangential_stiffness(double radius, const Material& i, const Material& j);

// Normal damping of the linear spring-dashpot, METHOD.md Contact:
//   c_n = -2 ln(eps) sqrt(M k_n) / sqrt(pi^2 + ln(eps)^2)
double normal_damping(double restitution, double mass, double stiffness);

// The damping ratio zeta = c / (2 sqrt(k m)) that gives restitution eps to a linear
// spring-dashpot, and back: eps = exp(-pi zeta / sqrt(1 - zeta^2)) (zeta >= 1: eps = 0).
double damping_ratio(double restitution);
double linear_restitution(double zeta);

}  // namespace washout::contact
