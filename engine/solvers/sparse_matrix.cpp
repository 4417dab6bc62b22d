#include "engine/solvers/sparse_matrix.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/solvers/row_sum.hpp"

namespace washout {

// A product with fewer non-zeros is a few tens of microseconds of work or less, where forking
// threads (and waiting at the barrier when another process holds a core) would cost as much.
// Counted in non-zeros, not rows: a 3D row holds about 50 (a 2D one about 20), so an 8,000-row
// 3D system is a 0.4 M non-zero product, worth both cores.
constexpr std::size_t kParallelNonzeros = 100000;

void CsrMatrix::multiply(const std::vector<double>& x, std::vector<double>& y) const {
  y.resize(rows);
#pragma omp parallel for schedule(static) if (nonzeros() > kParallelNonzeros)
  for (std::size_t i = 0; i < rows; ++i) {
    y[i] = sparse_row_dot(value.data(), column.data(), row_start[i], row_start[i + 1], x.data());
  }
}

void residual_norms(const CsrMatrix& A, const std::vector<std::vector<double>>& b,
                    const std::vector<std::vector<double>>& x, std::vector<double>& residual,
                    std::vector<double>& b_norm) {
  constexpr std::size_t kBlock = 2048;  // rows a partial sum covers
  constexpr std::size_t kGroup = 6;     // right-hand sides a row's entries are read for at once
  const std::size_t count = b.size(), n = A.rows;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  residual.assign(count, 0.0);
  b_norm.assign(count, 0.0);
  // Per block, then per pair: the squares of the residual and of b.
  std::vector<double> partial(blocks * count * 2, 0.0);
  // A group's x side by side, so that a column's six values share a cache line.
  // (The calling thread's buffer, shared by the threads of the loops below.)
  thread_local std::vector<double> packed_buffer;
  std::vector<double>& packed = packed_buffer;
  for (std::size_t first = 0; first < count; first += kGroup) {
    const std::size_t group = std::min(kGroup, count - first);
    packed.assign(n * kGroup, 0.0);
#pragma omp parallel for schedule(static) if (n > kBlock)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < group; ++k) packed[j * kGroup + k] = x[first + k][j];
#pragma omp parallel for schedule(static) if (A.nonzeros() > kParallelNonzeros)
    for (std::size_t block = 0; block < blocks; ++block) {
      double* sums = &partial[block * count * 2];
      const std::size_t end = std::min(n, (block + 1) * kBlock);
      for (std::size_t i = block * kBlock; i < end; ++i) {
        double ax[kGroup] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        for (std::int64_t e = A.row_start[i]; e < A.row_start[i + 1]; ++e) {
          const double v = A.value[e];
          const double* xj = &packed[std::size_t(A.column[e]) * kGroup];
          for (std::size_t k = 0; k < kGroup; ++k) ax[k] += v * xj[k];
        }
        for (std::size_t k = 0; k < group; ++k) {
          const double bi = b[first + k][i], r = bi - ax[k];
          sums[2 * (first + k)] += r * r;
          sums[2 * (first + k) + 1] += bi * bi;
        }
      }
    }
  }
  for (std::size_t block = 0; block < blocks; ++block)
    for (std::size_t k = 0; k < count; ++k) {
      residual[k] += partial[(block * count + k) * 2];
      b_norm[k] += partial[(block * count + k) * 2 + 1];
    }
  for (std::size_t k = 0; k < count; ++k) {
    residual[k] = std::sqrt(residual[k]);
    b_norm[k] = std::sqrt(b_norm[k]);
  }
}

}  // namespace washout
