#pragma once
// The energy guard of a run (docs/stability.md): the mechanical energy of the fluid and the
// dynamic bodies, kinetic plus potential in gravity, E = sum 1/2 m |u|^2 - m g.x, can only fall
// in a closed system (viscosity, shifting and the projection dissipate). It can rise only by the
// work of moving walls and prescribed bodies, which the budget bounds from above, step by step,
// by the largest pressure the fluid can exert times the wall's normal speed:
//   W <= sum_steps dt sum_w P_max A_w |v_w . n_w|,  P_max = rho0 (|g| H + u_max^2 / 2),
// over the first layer of moving boundary particles (A_w = d0^(dim-1)), H the fluid's height
// extent at the start. A run whose energy exceeds E(0) + W + tolerance * E_scale (E_scale =
// M_fluid |g| H, the potential energy the fluid can release) has gained energy from nowhere:
// a numerical instability, stopped before it shows as a runaway particle.
#include <string>

#include "engine/core/particles.hpp"
#include "engine/core/vec3.hpp"

namespace washout {

// Kinetic plus potential energy of the fluid particles (mass m each) [J; 2D: J/m].
double fluid_mechanical_energy(const Particles& p, double particle_mass, const Vec3& gravity);

// The largest power moving boundary particles (kinds MovingWall and RigidBody) can put into the
// fluid: sum_w P_max A_w |v_w . n_w| over the particles in the first layer (wall_distance < d0).
double moving_boundary_power_bound(const Particles& p, double d0, double max_pressure);

class EnergyBudget {
 public:
  // E(0), the scale M_fluid |g| H and the tolerance as a fraction of it.
  void start(double initial_energy, double scale, double tolerance);
  // Continues a budget saved with a checkpoint (E(0) and the work bound so far).
  void resume(double initial_energy, double work_bound) {
    initial_ = initial_energy;
    work_bound_ = work_bound;
  }
  // Adds the work bound of one step, dt * power_bound.
  void add_work_bound(double dt, double power_bound) { work_bound_ += dt * power_bound; }
  // E(t) - E(0) - W - tolerance * scale: > 0 means the run gained energy it cannot have.
  double excess(double energy) const;
  // The message of a fired guard, with the figures.
  std::string describe(double energy, double time) const;
  bool started() const { return started_; }
  double initial() const { return initial_; }
  double work_bound() const { return work_bound_; }
  double allowed(double) const { return initial_ + work_bound_ + tolerance_ * scale_; }

 private:
  bool started_ = false;
  double initial_ = 0.0, scale_ = 0.0, tolerance_ = 0.0, work_bound_ = 0.0;
};

}  // namespace washout
