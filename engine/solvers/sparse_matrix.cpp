#include "engine/solvers/sparse_matrix.hpp"

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

}  // namespace washout
