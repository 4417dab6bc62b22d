// Step 3 of METHOD.md, the corrector u^{n+1} = u* - (dt/rho0) <grad P^{n+1}>, and step 4, the
// position update x^{n+1} = x^n + dt u^{n+1} (two stages: the surface velocity smoothing,
// surface_smoothing.cpp, runs between them). The gradient is either the symmetric form
//   <grad P>_i = rho_i sum_j m_j (P_i/rho_i^2 + P_j/rho_j^2) grad W_ij   (default; conserves
//   momentum)
// or the difference form (1/rho_i) sum_j m_j (P_j - P_i) grad W_ij, both with equal volumes
// V = m/rho0 and the lattice normalisation. A boundary neighbour w carries the virtual pressure
// P_w = P_i + g_iw of the Neumann wall condition (see pressure_poisson.cpp).
#include <Eigen/Dense>
#include <algorithm>

#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {
namespace {

// Kernel gradient correction (Bonet & Lok 1999): L_i = (sum_j V (x_j - x_i) (x) grad W_ij)^-1 makes
// the difference-form gradient exact for linear fields even where the support is truncated (at
// the free surface). Returns false where too few neighbours make the matrix ill-conditioned.
bool gradient_correction_matrix(const SphContext& ctx, const NeighborList& list, const Particles& p,
                                std::size_t i, Eigen::Matrix3d& L) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
    const double f = ctx.volume * ctx.kernel.derivative_over_r(q.r);
    for (int a = 0; a < ctx.dim; ++a)
      for (int b = 0; b < ctx.dim; ++b) M(a, b) -= q.d[a] * f * q.d[b];  // (x_j - x_i)_a grad_b W
  });
  if (ctx.dim == 2) M(2, 2) = 1.0;
  const double det = M.determinant();
  if (!(std::abs(det) > 0.05)) return false;  // full support gives det ~ 1
  L = M.inverse();
  return true;
}

}  // namespace

void correct_velocity(const SphContext& ctx, const NeighborList& list, Particles& p,
                      const FluidWork& work, const WallConditions& walls, const Vec3& gravity,
                      double dt, bool symmetric_form) {
  const std::size_t n = p.fluid_count;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    // Free-surface particles (P = 0) see neighbours on one side only: the symmetric form would
    // give them about half the true gradient and let the surface sag. They take the difference
    // form with the kernel gradient correction, exact for a linear pressure field.
    const bool surface = work.free_surface[i] != 0;
    Eigen::Matrix3d L;
    const bool corrected = surface && gradient_correction_matrix(ctx, list, p, i, L);
    const double Pi = p.pressure[i];
    // A boundary neighbour carries the virtual pressure of the Neumann wall condition.
    const auto neighbor_pressure = [&](const NeighborPair& q) {
      return q.j < n ? p.pressure[q.j]
                     : Pi + wall_pressure_jump(ctx, p, work, walls, gravity, i, q.j, q.d, dt);
    };
    double grad[3];
    if (symmetric_form && !corrected)
      symmetric_gradient(ctx, list, p, i, Pi, neighbor_pressure, grad);
    else
      difference_gradient(ctx, list, p, i, Pi, neighbor_pressure, grad);
    if (corrected) {
      // L already normalises the sum: undo the lattice normalisation before applying it.
      const Eigen::Vector3d g =
          L * Eigen::Vector3d(grad[0], grad[1], grad[2]) / ctx.gradient_correction;
      for (int a = 0; a < ctx.dim; ++a) grad[a] = g[a];
    }
    for (int a = 0; a < ctx.dim; ++a)
      p.velocity[a][i] = work.u_star[a][i] - dt / ctx.rho0 * grad[a];
  }
}

double advance_positions(const SphContext& ctx, Particles& p, double dt) {
  const std::size_t n = p.fluid_count;
  double max_speed2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_speed2)
  for (std::size_t i = 0; i < n; ++i) {
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::Retired)) continue;  // left the domain
    double s2 = 0.0;
    for (int a = 0; a < ctx.dim; ++a) {
      const double v = p.velocity[a][i];
      p.position[a][i] = ctx.periodic.wrap(p.position[a][i] + dt * v, a);
      s2 += v * v;
    }
    max_speed2 = std::max(max_speed2, s2);
  }
  return std::sqrt(max_speed2);
}

}  // namespace washout
