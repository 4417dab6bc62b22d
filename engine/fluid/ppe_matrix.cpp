// The matrix of the stabilized PPE (METHOD.md step 2): the laplacian
//   <lap P>_i = sum_j V 2 (r_ij . grad W_ij) / (|r_ij|^2 + eta^2) (P_i - P_j) = -sum_j c_ij (P_i -
//   P_j)
// over the fluid neighbours, with the free surface in ghost form (pressure_poisson.cpp): a
// surface particle's missing neighbours add 2 |m_i| / d0 to its diagonal, m_i the first moment
// of the missing weights, m_i = -sum_present c_ij (x_j - x_i) (boundary neighbours are present).
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {

void assemble_ppe_matrix(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         bool ghost_surface, FluidWork& work, PpeRowFlags& flags) {
  const std::size_t n = p.fluid_count;
  CsrMatrix& A = work.matrix;
  const std::size_t rows = A.rows;
  A.row_start.assign(rows + 1, 0);
  flags.touches_surface.assign(rows, 0);
  flags.anchored.assign(rows, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    std::int64_t count = 1;  // the diagonal
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t j = list.index[k];
      if (j >= n) continue;
      if (work.unknown[j] >= 0) ++count;
      if (work.free_surface[j]) flags.touches_surface[row] = 1;
      if (work.unknown[j] < 0) flags.anchored[row] = 1;
    }
    if (work.free_surface[i]) flags.touches_surface[row] = flags.anchored[row] = 1;
    A.row_start[row + 1] = count;
  }
  for (std::size_t r = 0; r < rows; ++r) A.row_start[r + 1] += A.row_start[r];
  A.column.resize(A.row_start[rows]);
  A.value.resize(A.row_start[rows]);

#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    std::int64_t slot = A.row_start[row] + 1;
    double diagonal = 0.0;
    double missing[3] = {0, 0, 0};  // m_i
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      const double c = -ctx.laplacian_weight(q.r, q.r2);           // c_ij >= 0
      for (int a = 0; a < ctx.dim; ++a) missing[a] += c * q.d[a];  // -c (x_j - x_i)
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
    A.column[A.row_start[row]] = row;
    A.value[A.row_start[row]] = diagonal;
  }
}

}  // namespace washout
