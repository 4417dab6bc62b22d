// Step 3 of METHOD.md, the corrector u^{n+1} = u* - (dt/rho0) <grad P^{n+1}>, and step 4, the
// position update x^{n+1} = x^n + dt u^{n+1} (two stages: the surface velocity smoothing,
// surface_smoothing.cpp, runs between them). The gradient is either the symmetric form
//   <grad P>_i = rho_i sum_j m_j (P_i/rho_i^2 + P_j/rho_j^2) grad W_ij   (default; conserves
//   momentum)
// or the difference form (1/rho_i) sum_j m_j (P_j - P_i) grad W_ij, both with equal volumes
// V = m/rho0 and the lattice normalisation. In 3D the symmetric form's pair force takes the
// Wendland C2 shape of support 2 d0 in place of grad W (symmetric_kernel = "auto"): with the
// cubic spline a 3D lattice under pressure buckles into sliding columns (docs/method.md, the
// fifteenth session). A boundary neighbour w carries the virtual pressure
// P_w = P_i + g_iw of the Neumann wall condition (see pressure_poisson.cpp).
//
// Free-surface particles see neighbours on one side only. Where the PPE holds P = 0 at d0/2
// beyond them through ghost values (surface_pressure = "ghost"), their gradient is the
// difference form completed by the same ghosts, P_k = P_i (1 - 2 (r_k . n) / d0), whose share
//   sum_missing V (P_k - P_i) grad W_ik = (2 P_i / d0) (sum_present V r_ij (x) grad W_ij - I) n
// needs only the present neighbours (on a full lattice sum V r (x) grad W = I with the lattice
// normalisation), n the PPE's outward normal m_i / |m_i| (ppe_matrix.cpp). The gradient then
// sees the surface condition the PPE imposed: a surface particle pulled back by a negative
// pressure is pulled back, where a gradient over its present neighbours alone pushed it further
// out and the next step's divergence grew (docs/stability.md, ninth session). Otherwise
// (surface_gradient = "corrected", or P = 0 on the particles) the difference form takes the
// kernel gradient correction, exact for a linear field over the present neighbours.
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

// The ghost neighbours' share of surface particle i's difference-form gradient (above).
void add_ghost_share(const SphContext& ctx, const NeighborList& list, const Particles& p,
                     std::size_t i, double P_i, double grad[3]) {
  Eigen::Matrix3d present = Eigen::Matrix3d::Zero();  // sum_present V r_ij (x) grad W_ij
  Eigen::Vector3d m = Eigen::Vector3d::Zero();        // the PPE's m_i
  for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
    const double g = ctx.gradient_weight(q.r);  // grad W_ij = g (x_i - x_j), r_ij = x_j - x_i
    const double c = -ctx.laplacian_weight(q.r, q.r2);
    for (int a = 0; a < ctx.dim; ++a) {
      m[a] += c * q.d[a];
      for (int b = 0; b < ctx.dim; ++b) present(a, b) -= q.d[a] * g * q.d[b];
    }
  });
  const double m_norm = m.norm();
  if (!(m_norm > 0.0)) return;  // no missing weight: the PPE added no ghost either
  Eigen::Matrix3d full = Eigen::Matrix3d::Identity();  // the sum over a full support
  if (ctx.dim == 2) full(2, 2) = 0.0;
  const Eigen::Vector3d share = (2.0 * P_i / ctx.d0) * ((present - full) * (m / m_norm));
  for (int a = 0; a < ctx.dim; ++a) grad[a] += share[a];
}

}  // namespace

void correct_velocity(const SphContext& ctx, const NeighborList& list, Particles& p,
                      const FluidWork& work, const WallConditions& walls, const Vec3& gravity,
                      double dt, const GradientForms& forms) {
  const std::size_t n = p.fluid_count;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const bool surface = work.free_surface[i] != 0;
    // Ghost rows: surface particles whose pressure the PPE solved with ghost neighbours.
    const bool ghost = surface && forms.ghost_surface && work.unknown[i] >= 0;
    Eigen::Matrix3d L = Eigen::Matrix3d::Identity();  // set when corrected; initialised for -Wall
    const bool corrected = surface && !ghost && gradient_correction_matrix(ctx, list, p, i, L);
    const double Pi = p.pressure[i];
    // A boundary neighbour carries the virtual pressure of the Neumann wall condition.
    const auto neighbor_pressure = [&](const NeighborPair& q) {
      return q.j < n ? p.pressure[q.j]
                     : Pi + wall_pressure_jump(ctx, p, work, walls, gravity, i, q.j, q.d, dt);
    };
    // The particle's own normalisation (gradient_scale.cpp): a pair factor in the symmetric form,
    // the particle's factor in the difference form; the surface's forms are exact already.
    const auto pair_scale = [&](const NeighborPair& q) {
      return gradient_pair_scale(work, n, i, q.j);
    };
    double grad[3];
    if (forms.symmetric && !ghost && !corrected) {
      symmetric_gradient(ctx, list, p, i, Pi, neighbor_pressure, pair_scale, grad);
    } else {
      difference_gradient(ctx, list, p, i, Pi, neighbor_pressure, grad);
      if (!surface && !work.gradient_scale.empty())
        for (int a = 0; a < ctx.dim; ++a) grad[a] *= work.gradient_scale[i];
    }
    if (ghost) add_ghost_share(ctx, list, p, i, Pi, grad);
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
    if (p.retired(i)) continue;  // left the domain
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
