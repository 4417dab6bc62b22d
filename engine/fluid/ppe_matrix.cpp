// The matrix of the stabilized PPE (METHOD.md step 2): the laplacian
//   <lap P>_i = sum_j V 2 (r_ij . grad W_ij) / (|r_ij|^2 + eta^2) (P_i - P_j) = -sum_j c_ij (P_i -
//   P_j)
// over the fluid neighbours, with the free surface in ghost form (pressure_poisson.cpp): a
// surface particle's missing neighbours add 2 |m_i| / d0 to its diagonal, m_i the first moment
// of the missing weights, m_i = -sum_present c_ij (x_j - x_i) (boundary neighbours are present).
//
// The corrector's symmetric gradient (corrector.cpp) is the difference form plus a zero-order
// term, sum_j V (P_i + P_j) grad W_ij = sum_j V (P_j - P_i) grad W_ij + 2 P_i S_i with
// S_i = sum_j V grad W_ij over all neighbours, boundary included: zero on a full support, as
// large as at a surface particle where the support is cut (the tip of a thin surge, the water
// by a face moving away from it) and the density still counts the particle as inside. The
// laplacian stands for the difference form; the zero-order term moves particle i by
// -(dt/rho0) 2 P_i S_i and changes its own divergence by (dt/rho0) 2 |S_i|^2 P_i, so a row the
// symmetric gradient will correct gains 2 |S_i|^2 on its diagonal (2 S_i . S_i^K where the
// symmetric gradient's pair force has its own kernel K, the Wendland shape of 3D runs: the
// corrector moves the particle along S_i^K, the divergence sees it through S_i). Without it the
// projection overshoots there and the next step answers with a pressure of the other sign: in the
// 2D wash-out at d0 = 0.005 m the water beside the girder alternated between -0.5 and +0.6 MPa step
// to step, growing, with the body held still as with it free (docs/method.md, the fourteenth
// session).
#include <algorithm>

#include "engine/core/sph_operators.hpp"
#include "engine/core/vector_growth.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {

void assemble_ppe_matrix(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         bool ghost_surface, bool symmetric_gradient, FluidWork& work,
                         PpeRowFlags& flags) {
  const std::size_t n = p.fluid_count;
  CsrMatrix& A = work.matrix;
  const std::size_t rows = A.rows;
  A.row_start.assign(rows + 1, 0);
  flags.touches_surface.assign(rows, 0);
  flags.anchored.assign(rows, 0);
  // With one row per fluid particle (rows == n: the stable layout, or every particle solved
  // for), a particle whose pressure is given holds an identity row, P = 0 with a zero right-hand
  // side, anchored so that no pressure level is fixed there; otherwise it holds no row.
  const bool identity_rows = rows == n;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) {
      if (identity_rows) {
        A.row_start[i + 1] = 1;
        flags.anchored[i] = 1;
      }
      continue;
    }
    // The flags gathered in locals and stored once: a byte stored in the loop might alias any
    // array's address, which the compiler would then load again at every neighbour.
    std::int64_t count = 1;  // the diagonal
    bool touches_surface = work.free_surface[i] != 0, anchored = touches_surface;
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t j = list.index[k];
      if (j >= n) continue;
      if (work.unknown[j] >= 0) ++count;
      touches_surface |= work.free_surface[j] != 0;
      anchored |= work.unknown[j] < 0;
    }
    flags.touches_surface[row] = touches_surface;
    flags.anchored[row] = anchored;
    A.row_start[row + 1] = count;
  }
  for (std::size_t r = 0; r < rows; ++r) A.row_start[r + 1] += A.row_start[r];
  grow_to(A.column, static_cast<std::size_t>(A.row_start[rows]));
  grow_to(A.value, static_cast<std::size_t>(A.row_start[rows]));

#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) {
      if (identity_rows) {
        A.column[A.row_start[i]] = static_cast<std::int32_t>(i);
        A.value[A.row_start[i]] = 1.0;
      }
      continue;
    }
    std::int64_t slot = A.row_start[row] + 1;
    double diagonal = 0.0;
    double missing[3] = {0, 0, 0};    // m_i
    double cut[3] = {0, 0, 0};        // S_i
    double cut_force[3] = {0, 0, 0};  // S_i of the symmetric gradient's own kernel
    // The rows the corrector takes in symmetric form: all but the surface's (corrector.cpp).
    const bool own_term = symmetric_gradient && !work.free_surface[i];
    const bool own_kernel = own_term && ctx.symmetric_has_own_kernel();
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      const double c = -ctx.laplacian_weight(q.r, q.r2);  // c_ij >= 0
      const double g = own_term ? ctx.gradient_weight(q.r) : 0.0;
      const double k = (own_kernel ? ctx.symmetric_gradient_weight(q.r) : g) *
                       (own_term ? gradient_pair_scale(work, n, i, q.j) : 1.0);
      for (int a = 0; a < ctx.dim; ++a) {
        missing[a] += c * q.d[a];  // -c (x_j - x_i)
        cut[a] += g * q.d[a];
        cut_force[a] += k * q.d[a];
      }
      if (q.j >= n) return;
      diagonal += c;
      if (work.unknown[q.j] >= 0) {
        A.column[slot] = work.unknown[q.j];
        A.value[slot++] = -c;
      }
    });
    if (ghost_surface && work.free_surface[i]) {
      double m2 = 0.0;
      for (int a = 0; a < ctx.dim; ++a) m2 += missing[a] * missing[a];
      diagonal += 2.0 * std::sqrt(m2) / ctx.d0;
    }
    // Never below zero, so that the matrix stays positive definite: S_i . S_i^K can be negative
    // where both are small (inside an irregular block, 0.5 % of a diagonal at most in
    // tests/unit/test_pressure_poisson.cpp); where the support is cut they point the same way.
    if (own_term)
      diagonal += std::max(
          0.0, 2.0 * (cut[0] * cut_force[0] + cut[1] * cut_force[1] + cut[2] * cut_force[2]));
    A.column[A.row_start[row]] = row;
    A.value[A.row_start[row]] = diagonal;
  }
}

}  // namespace washout
