#pragma once
// The stages of one stabilized-ISPH step (METHOD.md "One time step"), one function per
// equation, each implemented in the file named after it. The Simulation composes them.
#include <cstddef>
#include <cstdint>
#include <limits>

#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"
#include "engine/fluid/fluid_work.hpp"

namespace washout {

// <rho>_i = sum_j m_j W_ij over fluid and boundary neighbours, scaled so that a full-support
// lattice gives rho0 (summation_density.cpp).
void compute_summation_density(const SphContext& ctx, const NeighborList& list, Particles& p);
// The same, and in the same walk each fluid particle's gradient moment m_i into
// work.gradient_moment (gradient_scale.cpp), which reads only the pairs' distances too: one walk
// over the neighbours' positions instead of two (docs/performance.md, thirty-fifth session).
void compute_summation_density_and_gradient_moment(const SphContext& ctx, const NeighborList& list,
                                                   Particles& p, bool symmetric, FluidWork& work);

// Free surface: <rho>_i < threshold * rho0 (kSurface), or no fluid neighbour (kIsolated, P = 0).
// Returns the count (free_surface.cpp).
std::size_t detect_free_surface(const SphContext& ctx, const NeighborList& list, const Particles& p,
                                double threshold, FluidWork& work);

// Smagorinsky sub-particle-scale eddy viscosity nu_t = (C_s d0)^2 |S| (turbulence_smagorinsky.cpp).
void compute_eddy_viscosity(const SphContext& ctx, const NeighborList& list, const Particles& p,
                            double smagorinsky_constant, FluidWork& work);

// Step 1, predictor: u* = u + dt (nu <lap u> + (1/rho0) <div tau> + g) (predictor.cpp). With
// eddy_viscosity_at_walls false a wall pair takes the molecular viscosity only.
void predict_velocity(const SphContext& ctx, const NeighborList& list, const Particles& p,
                      double viscosity, const Vec3& gravity, double dt, FluidWork& work,
                      bool eddy_viscosity_at_walls = true);

// Wall function: the first fluid layer loses the part of the smooth-wall law-of-the-wall stress
// that the resolved viscous term does not carry, scaled by (1 - slip) (wall_shear.cpp).
void apply_wall_shear(const SphContext& ctx, const NeighborList& list, const Particles& p,
                      const WallConditions& walls, double viscosity, double dt, FluidWork& work);
// u_* of the law of the wall for a tangential speed u_t at distance y (viscous sublayer below
// y+ = 11.06, log layer above).
double friction_velocity(double u_t, double y, double nu);

struct PpeStatistics {
  std::size_t unknowns = 0;
  std::size_t nonzeros = 0;
  std::size_t pinned_components = 0;  // closed fluid regions whose pressure level was fixed
};

// Step 2, the stabilized PPE (pressure_poisson.cpp):
//   <lap P>_i = (rho0/dt) <div u*>_i + alpha (rho0 - <rho>_i) / dt^2,  P = 0 on the free surface
// (ghost_surface: at d0/2 beyond the surface particles; otherwise on them), walls by the Neumann
// condition through virtual pressures P_w = P_i + g_iw.
// walls: what the scene fixes for its walls (none: a fluid without boundary particles).
// symmetric_gradient: the corrector takes the symmetric form inside the fluid (GradientForms),
// whose zero-order term the matrix then holds (ppe_matrix.cpp).
// stable_rows: one row per fluid particle, in particle order, those whose pressure is given
// taking identity rows (number_pressure_unknowns, pressure_poisson_parts.hpp).
PpeStatistics assemble_pressure_poisson(const SphContext& ctx, const NeighborList& list,
                                        const Particles& p, const Vec3& gravity, double alpha,
                                        double dt, bool ghost_surface, FluidWork& work,
                                        const WallConditions& walls = WallConditions::none(),
                                        bool symmetric_gradient = false, bool stable_rows = false);
// The volume error of particles within a support of the free surface, where the summation
// density cannot tell it (surface_strain.cpp): before the positions advance by dt u, each such
// particle (a free-surface neighbour, not on the surface itself) adds dt <div u>_i to
// work.surface_strain; every other particle's is reset to 0.
void accumulate_surface_strain(const SphContext& ctx, const NeighborList& list, const Particles& p,
                               double dt, FluidWork& work);
// The pressure gradient's normalisation by each particle's own neighbours (gradient_scale.cpp):
// work.gradient_scale[i] = 1 / m_i, m_i the gradient moment of the kernel the corrector's form
// uses (symmetric: its own kernel), measured where the support is full and averaged from those
// neighbours within a support of the free surface.
void compute_gradient_scale(const SphContext& ctx, const NeighborList& list, const Particles& p,
                            bool symmetric, FluidWork& work);
// Its two parts: the moments (a walk of their own; compute_summation_density_and_gradient_moment
// takes them in the density's), then the scales from the moments and the free surface.
void compute_gradient_moment(const SphContext& ctx, const NeighborList& list, const Particles& p,
                             bool symmetric, FluidWork& work);
void scale_from_gradient_moment(const NeighborList& list, const Particles& p, FluidWork& work);
// The pair weight V (dK/dr) / r of the gradient moment (with the lattice normalisation), K the
// kernel of the corrector's form: its own in the symmetric form of 3D. A pair adds -weight r^2.
inline double gradient_moment_weight(const SphContext& ctx, bool own_kernel, double r) {
  return own_kernel ? ctx.symmetric_gradient_weight(r) : ctx.gradient_weight(r);
}
// Copies the solution back to the fluid particles' pressure (P = 0 on the free surface).
void scatter_pressure(const FluidWork& work, Particles& p);
// Initial guess for an iterative solve: the previous pressure of each unknown.
void gather_pressure_guess(const Particles& p, FluidWork& work);

// The boundary particle nearest to fluid particle i among its neighbours (and its squared
// distance), or none (index p.size()) if it sees none; bodies' particles left out if asked.
// Its plane stands for the wall's surface in the wall shear and the wall's clearance.
struct NearestBoundary {
  std::size_t index;
  double r2;
};
inline NearestBoundary nearest_boundary(const SphContext& ctx, const NeighborList& list,
                                        const Particles& p, std::size_t i, bool skip_bodies) {
  const std::size_t n = p.fluid_count;
  NearestBoundary nearest{p.size(), std::numeric_limits<double>::max()};
  for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
    const std::size_t w = list.index[k];
    if (w < n || (skip_bodies && p.body[w] >= 0)) continue;
    double d[3];
    ctx.displacement(p, i, w, d);
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (r2 < nearest.r2) nearest = {w, r2};
  }
  return nearest;
}

// The virtual pressure of boundary particle w as seen by fluid particle i, P_w = P_i + g_iw:
//   normal to the wall, the Neumann condition of the projection, dP/dn = (rho0/dt)(u*_i - u_w).n,
//   which makes the corrected velocity follow the wall; along the wall, the hydrostatic
//   variation rho0 g_t, so that a particle beside a vertical wall keeps its full pressure support
//   (the wall's tangential share of <grad P> would otherwise be missing).
inline double wall_pressure_jump(const SphContext& ctx, const Particles& p, const FluidWork& work,
                                 const WallConditions& walls, const Vec3& gravity, std::size_t i,
                                 std::size_t w, const double d_iw[3], double dt) {
  if (walls.dynamic) {
    // dP/dn = rho0 (g - a_w).n: the fluid keeps the wall's normal acceleration; along the wall
    // the hydrostatic variation. A wall sliding along itself (a gate lifted) leaves P alone.
    double gr = 0.0, an = 0.0, rn = 0.0;
    for (int a = 0; a < ctx.dim; ++a) {
      const double n = p.normal[a][w], r = -d_iw[a];
      gr += gravity[a] * r;
      an += work.boundary.wall_acceleration[a][w] * n;
      rn += r * n;
    }
    // Only where i lies in front of w's face (r . n < 0): beside a convex corner the fluid sees
    // the other face's particles, whose normal motion is not its own. A squeeze film does not
    // follow the body that closes it (squeeze_film.hpp).
    return ctx.rho0 * (rn < 0.0 && !work.boundary.in_film(i) ? gr - an * rn : gr);
  }
  double un = 0.0, rn = 0.0, gr = 0.0, gn = 0.0;
  for (int a = 0; a < ctx.dim; ++a) {
    const double n = p.normal[a][w], r = -d_iw[a];  // r = x_w - x_i
    un += (work.u_star[a][i] - p.velocity[a][w]) * n;
    rn += r * n;
    gr += gravity[a] * r;
    gn += gravity[a] * n;
  }
  // A free-surface particle leaving a wall separates from it: the wall pushes, it does not pull
  // (its pressure would otherwise drop below the air's to hold the particle on the wall).
  if (work.free_surface[i] && un > 0.0) un = 0.0;
  return ctx.rho0 * (un / dt * rn + (gr - gn * rn));
}

// The corrector's gradient forms, resolved once from the parameters (corrector.cpp).
struct GradientForms {
  bool symmetric = true;       // interior: symmetric (momentum-conserving) or difference form
  bool ghost_surface = false;  // surface rows: completed by the PPE's ghost values, or corrected
};

// Step 3, corrector: u^{n+1} = u* - (dt/rho0) <grad P> (corrector.cpp).
void correct_velocity(const SphContext& ctx, const NeighborList& list, Particles& p,
                      const FluidWork& work, const WallConditions& walls, const Vec3& gravity,
                      double dt, const GradientForms& forms);
// The fraction of a step of Courant number dt U / h, from the fraction set for a step of the
// reference Courant number: 1 - (1 - f_ref)^(C / C_ref), so the smoothing is a rate in the
// distance travelled and two half steps smooth as much as one whole. A reference of 0: the
// fraction is taken every step, whatever its size.
double surface_smoothing_for_step(double fraction_at_reference, double courant,
                                  double reference_courant);
// Free-surface particles take this fraction of their neighbourhood's mean velocity (XSPH on the
// surface only; surface_smoothing.cpp).
void smooth_surface_velocity(const SphContext& ctx, const NeighborList& list, Particles& p,
                             const FluidWork& work, double surface_smoothing,
                             std::vector<double>& smoothed);
// Step 4: x^{n+1} = x^n + dt u^{n+1} (corrector.cpp). Returns the largest fluid speed.
double advance_positions(const SphContext& ctx, Particles& p, double dt);

// density_kick = "positions" (density_kick.cpp): the density term moves the particles but does
// not stay in their velocity. The relative residual its loose second solve stops at: 0.1 kept
// the whole still-tank cure of the exact solve, 0.3 most of it (docs/stability.md).
constexpr double kDensityKickTolerance = 0.1;
// work.density_pressure from the second solve's work.density_solution (0 where not solved for).
void scatter_density_pressure(const FluidWork& work, std::size_t fluid_count,
                              std::vector<double>& pressure);
// The corrector with P - P_d (kept in work.density_kick) and with P (in the velocity, which
// moves the particles); work.density_kick becomes their difference and the pressure P - P_d.
void correct_velocity_keeping_density_kick(const SphContext& ctx, const NeighborList& list,
                                           Particles& p, FluidWork& work,
                                           const WallConditions& walls, const Vec3& gravity,
                                           double dt, const GradientForms& forms);
// After the move: the kick taken back out of the velocity.
void remove_density_kick(const FluidWork& work, Particles& p);

// Fickian particle shifting after the position update (particle_shifting.cpp):
//   delta r = -(A h^2 + A_u h |u| dt) grad C.
void shift_particles(const SphContext& ctx, const NeighborList& list, Particles& p,
                     const FluidWork& work, double coefficient, double speed_coefficient, double dt,
                     std::vector<double>& scratch);

}  // namespace washout
