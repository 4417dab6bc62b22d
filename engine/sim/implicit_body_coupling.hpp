#pragma once
// The pressure and the dynamic bodies' velocities solved as one system (docs/bodies.md
// "Coupling"). Taken one after the other, as METHOD.md's explicit step reads, a velocity error e
// of a body comes back from the pressure as -(m_f / M) e in the next step, m_f the discrete added
// mass of the fluid around it: a body lighter than the water it pushes (a floating box, a girder
// lifted by the wave) blows up within a few steps. Both the PPE right-hand side and the surface
// load are linear in the bodies' velocities xi = (T, w), so with the pressure P0 solved at xi^n
//   P(xi)  = P0 + sum_k S_k (xi - xi^n)_k,         A S_k = B_k  (wall_velocity_response.hpp),
//   F(xi)  = F(P0) + G (xi - xi^n),                 G_k = F(S_k) (linear surface load),
// and Newton-Euler over the step, M (xi - xi^n) / dt = F(xi) + M g + F_c - w x I w, becomes
//   (M / dt - G) (xi - xi^n) = F(P0) + M g + F_c - w x I w,
// a small dense system (3 unknowns per body in 2D, 6 in 3D). F_c is the contact load of the
// previous step; the contact sub-steps then integrate with the fluid load F(xi) held. The
// fluid pressure is updated to P(xi) and the walls' acceleration to (xi - xi^n) / dt, so the
// corrector moves the fluid with the bodies' new velocities.
#include <vector>

#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"
#include "engine/fluid/fluid_work.hpp"
#include "engine/solvers/linear_solver.hpp"

namespace washout {

class RigidBodySystem;

struct CouplingReport {
  int solves = 0;       // extra pressure solves (one per body degree of freedom, plus corrections)
  long iterations = 0;  // their iterations in all
};

// Relative residuals: the pressure solve's (solver_tolerance), and the one the response fields
// are solved to, relative to the largest response of their kind (coupling_tolerance;
// implicit_body_coupling.cpp says why it may be looser).
struct CouplingTolerances {
  double pressure = 1e-6;
  double response = 1e-6;
};

class ImplicitBodyCoupling {
 public:
  // After the PPE has been solved at the bodies' current velocities (p.pressure = P0): sets the
  // bodies' fluid loads, p.pressure and work.wall_acceleration of the body particles.
  CouplingReport couple(const SphContext& ctx, const NeighborList& list, const NeighborGrid& grid,
                        Particles& p, FluidWork& work, LinearSolver& solver,
                        RigidBodySystem& bodies, const Vec3& gravity, double dt,
                        const CouplingTolerances& tolerances);

  // The last step's response fields S_k per fluid particle: the warm start of the next solves,
  // part of a run's state (a checkpoint saves and restores them).
  const std::vector<std::vector<double>>& warm_start() const { return previous_; }
  void set_warm_start(std::vector<std::vector<double>> fields) { previous_ = std::move(fields); }

 private:
  std::vector<std::vector<double>> response_, solution_;
  std::vector<double> residual_;               // |B_k - A S_k| of each response
  std::vector<std::vector<double>> previous_;  // S_k per fluid particle, the next warm start
  std::vector<double> coupled_, coupled_rhs_;  // the coupled pressure (rows) and its right side
  std::vector<double> field_rows_;             // the coupled pressure's change, P - P0
  std::vector<std::uint8_t> beside_mark_;      // fluid_beside_bodies' scratch
  std::vector<std::uint32_t> beside_;          // the fluid within 2h of a dynamic body
};

}  // namespace washout
