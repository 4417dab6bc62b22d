#include "engine/sim/energy_budget.hpp"

#include <cmath>
#include <sstream>

namespace washout {

double fluid_mechanical_energy(const Particles& p, double particle_mass, const Vec3& gravity) {
  const std::size_t n = p.fluid_count;
  double energy = 0.0;
#pragma omp parallel for reduction(+ : energy) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double e = 0.0;
    for (int a = 0; a < p.dim; ++a)
      e += 0.5 * p.velocity[a][i] * p.velocity[a][i] - gravity[a] * p.position[a][i];
    energy += particle_mass * e;
  }
  return energy;
}

double moving_boundary_power_bound(const Particles& p, double d0, double max_pressure) {
  const double area = p.dim == 3 ? d0 * d0 : d0;
  double power = 0.0;
#pragma omp parallel for reduction(+ : power) schedule(static)
  for (std::size_t w = p.fluid_count; w < p.size(); ++w) {
    const auto kind = static_cast<ParticleKind>(p.kind[w]);
    if (kind != ParticleKind::MovingWall && kind != ParticleKind::RigidBody) continue;
    if (!(p.wall_distance[w] < d0)) continue;
    double vn = 0.0;
    for (int a = 0; a < p.dim; ++a) vn += p.velocity[a][w] * p.normal[a][w];
    power += max_pressure * area * std::abs(vn);
  }
  return power;
}

void EnergyBudget::start(double initial_energy, double scale, double tolerance) {
  started_ = true;
  initial_ = initial_energy;
  scale_ = scale;
  tolerance_ = tolerance;
  work_bound_ = 0.0;
}

double EnergyBudget::excess(double energy) const {
  return energy - (initial_ + work_bound_ + tolerance_ * scale_);
}

std::string EnergyBudget::describe(double energy, double time) const {
  std::ostringstream m;
  m.precision(4);
  m << "energy gain: the mechanical energy of the fluid and bodies is " << energy - initial_
    << " J above its start at t = " << time << " s, more than moving walls and bodies can have "
    << "done (" << work_bound_
    << " J at most) plus the tolerance energy_gain_limit = " << tolerance_ << " x " << scale_
    << " J (the potential energy the fluid can release)";
  return m.str();
}

}  // namespace washout
