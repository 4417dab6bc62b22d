// Step 2 of METHOD.md, the stabilized pressure Poisson equation (Asai et al. 2012):
//   <lap P>_i = (rho0/dt) <div u*>_i + alpha (rho0 - <rho>_i) / dt^2
// Unknowns are the fluid particles that are not on the free surface (those take P = 0) nor in a
// squeeze film (those take work.film_pressure, squeeze_film.hpp).
// With the laplacian written as <lap P>_i = -sum_j c_ij (P_i - P_j), c_ij >= 0, every row reads
//   sum_j c_ij (P_i - P_j) = -b_i,
// a symmetric positive definite system when particle volumes are equal.
// Walls enter through the Neumann condition dP/dn = (rho0/dt)(u* - u_wall).n: boundary particle
// w contributes c_iw (P_i - P_w) with P_w = P_i + g_iw (wall_pressure_jump), a known term that
// moves to the right-hand side, so the matrix stays symmetric. The divergence uses fluid
// neighbours only; the wall's share of it is what the Neumann term imposes.
//
// Free surface, ghost form (default): P = 0 holds at the surface itself, d0/2 beyond the centres
// of the surface particles, not on them. A surface particle i is an unknown; the neighbours its
// support is missing (air) are ghosts whose pressure is the linear extrapolation through P_i
// that vanishes at d0/2 along the outward normal n: P_k = P_i (1 - 2 (r_k . n) / d0). Their
// share of the laplacian, sum_k c_ik (P_i - P_k) = P_i (2/d0) sum_k c_ik (r_k . n), needs only
// the first moment of the missing weights, and on a full lattice sum_k c_ik r_k = 0, so
//   m_i = sum_missing c_ik r_k = - sum_present c_ij (x_j - x_i),   n = m_i / |m_i|,
// and the row gains the diagonal term 2 |m_i| / d0: symmetric and positive, no extra unknowns.
// Imposing P = 0 on the particles themselves (surface_pressure = "on_particles") puts the
// surface half a spacing too low: a hydrostatic error of d0/(2H) and floating bodies too deep.
#include <cmath>
#include <numeric>

#include "engine/fluid/isph_stages.hpp"

namespace washout {
namespace {

// Connected components of the unknowns, by union-find over the matrix pattern.
struct UnionFind {
  std::vector<std::int32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

PpeStatistics assemble_pressure_poisson(const SphContext& ctx, const NeighborList& list,
                                        const Particles& p, const Vec3& gravity, double alpha,
                                        double dt, bool ghost_surface, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  // A particle whose pressure is given, not solved for: P = 0 on it (an isolated drop, or any
  // surface particle without the ghost form) or the squeeze-film pressure.
  const auto dirichlet = [&](std::size_t i) {
    return work.in_film(i) || work.free_surface[i] == FluidWork::kIsolated ||
           (!ghost_surface && work.free_surface[i] == FluidWork::kSurface);
  };
  work.unknown.assign(n, -1);
  std::size_t rows = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!dirichlet(i)) work.unknown[i] = static_cast<std::int32_t>(rows++);

  CsrMatrix& A = work.matrix;
  A.rows = rows;
  A.row_start.assign(rows + 1, 0);
  // touches_surface: within a support of the surface (no density-invariance term there);
  // anchored: the row holds a known pressure (a Dirichlet neighbour or its own ghosts), so its
  // fluid region's pressure level is fixed.
  std::vector<std::uint8_t> touches_surface(rows, 0), anchored_row(rows, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    std::int64_t count = 1;  // the diagonal
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t j = list.index[k];
      if (j < n && work.unknown[j] >= 0) ++count;
      if (j < n && work.free_surface[j]) touches_surface[row] = 1;
      if (j < n && work.unknown[j] < 0) anchored_row[row] = 1;
    }
    if (work.free_surface[i]) touches_surface[row] = anchored_row[row] = 1;
    A.row_start[row + 1] = count;
  }
  for (std::size_t r = 0; r < rows; ++r) A.row_start[r + 1] += A.row_start[r];
  A.column.resize(A.row_start[rows]);
  A.value.resize(A.row_start[rows]);
  work.rhs.assign(rows, 0.0);

  const double g_scale = ctx.gradient_correction * ctx.volume;
  const double density_scale = alpha * ctx.rho0 / (dt * dt);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    std::int64_t slot = A.row_start[row] + 1;
    double diagonal = 0.0, divergence = 0.0, wall_term = 0.0;
    double missing[3] = {0, 0, 0};  // m_i, first moment of the missing laplacian weights
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t j = list.index[k];
      double d[3];
      ctx.displacement(p, i, j, d);
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double r = std::sqrt(r2);
      const double c = -ctx.laplacian_weight(r, r2);             // c_ij >= 0
      for (int a = 0; a < ctx.dim; ++a) missing[a] += c * d[a];  // -c (x_j - x_i)
      if (j < n) {
        diagonal += c;
        if (work.unknown[j] >= 0) {
          A.column[slot] = work.unknown[j];
          A.value[slot++] = -c;
        } else if (work.in_film(j)) {
          wall_term += c * work.film_pressure[j];  // a known pressure, as P = 0 on a drop
        }
        // Difference-form divergence: sum_j V (u*_j - u*_i) . grad W_ij
        const double f = g_scale * ctx.kernel.derivative_over_r(r);
        for (int a = 0; a < ctx.dim; ++a)
          divergence += f * d[a] * (work.u_star[a][j] - work.u_star[a][i]);
      } else {
        wall_term += c * wall_pressure_jump(ctx, p, work, gravity, i, j, d, dt);
        if (work.dynamic_wall) {
          // The wall's share of <div u*>: the wall's velocity plus the normal part of the
          // virtual marker's velocity relative to it (the fluid's, mirrored at the start of the
          // step), with the same body-force increment dt g as the fluid (the wall jump above
          // carries g - a_w). The tangential part is left out: beyond the tip of a flow the
          // markers are dry, and their tangential velocity would read as a divergence.
          double marker_un = 0.0;
          for (int a = 0; a < ctx.dim; ++a)
            marker_un += (work.marker_velocity[a][j] - p.velocity[a][j]) * p.normal[a][j];
          const double f = g_scale * ctx.kernel.derivative_over_r(r);
          for (int a = 0; a < ctx.dim; ++a)
            divergence += f * d[a] *
                          (p.velocity[a][j] + marker_un * p.normal[a][j] + dt * gravity[a] -
                           work.u_star[a][i]);
        }
      }
    }
    if (ghost_surface && work.free_surface[i]) {
      // Ghost air beyond the surface (see the top of this file): 2 |m_i| / d0 on the diagonal.
      double m2 = 0.0;
      for (int a = 0; a < ctx.dim; ++a) m2 += missing[a] * missing[a];
      diagonal += 2.0 * std::sqrt(m2) / ctx.d0;
    }
    A.column[A.row_start[row]] = row;
    A.value[A.row_start[row]] = diagonal;
    // Within a kernel support of the free surface the summation density is low only because the
    // support is truncated, not because the fluid expanded: the density-invariance term would
    // read that deficit as an error and pull the surface in. It acts on interior particles only.
    const double density_error = touches_surface[row] ? 0.0 : (ctx.rho0 - p.density[i]) / ctx.rho0;
    const double source = ctx.rho0 / dt * divergence + density_scale * density_error;
    work.rhs[row] = -source + wall_term;
  }

  // A closed body of fluid with no free surface (a filled tank, a periodic channel) defines its
  // pressure only up to a constant: make its right-hand side compatible and fix one value.
  PpeStatistics stats;
  stats.unknowns = rows;
  stats.nonzeros = A.nonzeros();
  UnionFind components(rows);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::int64_t k = A.row_start[r] + 1; k < A.row_start[r + 1]; ++k)
      components.unite(static_cast<std::int32_t>(r), A.column[k]);
  std::vector<std::uint8_t> anchored(rows, 0);
  for (std::size_t r = 0; r < rows; ++r)
    if (anchored_row[r]) anchored[components.find(static_cast<std::int32_t>(r))] = 1;
  std::vector<double> rhs_sum(rows, 0.0);
  std::vector<std::int64_t> size(rows, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    const auto root = components.find(static_cast<std::int32_t>(r));
    if (anchored[root]) continue;
    rhs_sum[root] += work.rhs[r];
    ++size[root];
  }
  for (std::size_t r = 0; r < rows; ++r) {
    const auto root = components.find(static_cast<std::int32_t>(r));
    if (anchored[root]) continue;
    work.rhs[r] -= rhs_sum[root] / size[root];
    if (static_cast<std::size_t>(root) == r) {
      A.value[A.row_start[r]] *= 2.0;  // a Dirichlet-like anchor: P_root stays near zero
      ++stats.pinned_components;
    }
  }
  return stats;
}

void gather_pressure_guess(const Particles& p, FluidWork& work) {
  work.solution.assign(work.matrix.rows, 0.0);
  for (std::size_t i = 0; i < p.fluid_count; ++i)
    if (work.unknown[i] >= 0) work.solution[work.unknown[i]] = p.pressure[i];
}

void scatter_pressure(const FluidWork& work, Particles& p) {
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.fluid_count; ++i)
    p.pressure[i] = work.unknown[i] >= 0 ? work.solution[work.unknown[i]]
                    : work.in_film(i)    ? work.film_pressure[i]
                                         : 0.0;
}

}  // namespace washout
