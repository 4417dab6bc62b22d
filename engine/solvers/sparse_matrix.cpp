#include "engine/solvers/sparse_matrix.hpp"

#include <algorithm>

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

namespace {

constexpr std::size_t kGroup = 6;  // vectors a row's entries are read for at once

// Vectors x[first, first + group) side by side, so that a column's values share a cache line.
// The buffer is the calling thread's, shared by the threads of the loops that read it.
const std::vector<double>& packed_group(const std::vector<const std::vector<double>*>& x,
                                        std::size_t first, std::size_t group, std::size_t n) {
  thread_local std::vector<double> buffer;
  std::vector<double>& packed = buffer;
  packed.resize(n * kGroup);  // every value written below: no zeroing pass first
#pragma omp parallel for schedule(static) if (n > 4096)
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t k = 0; k < group; ++k) packed[j * kGroup + k] = (*x[first + k])[j];
    for (std::size_t k = group; k < kGroup; ++k) packed[j * kGroup + k] = 0.0;
  }
  return packed;
}

// ax[k] = (A x_k)_i for the packed group.
inline void row_products(const CsrMatrix& A, std::size_t i, const std::vector<double>& packed,
                         double ax[kGroup]) {
  for (std::size_t k = 0; k < kGroup; ++k) ax[k] = 0.0;
  for (std::int64_t e = A.row_start[i]; e < A.row_start[i + 1]; ++e) {
    const double v = A.value[e];
    const double* xj = &packed[std::size_t(A.column[e]) * kGroup];
    for (std::size_t k = 0; k < kGroup; ++k) ax[k] += v * xj[k];
  }
}

}  // namespace

void multiply_many(const CsrMatrix& A, const std::vector<const std::vector<double>*>& x,
                   const std::vector<std::vector<double>*>& y) {
  const std::size_t count = x.size(), n = A.rows;
  for (std::size_t first = 0; first < count; first += kGroup) {
    const std::size_t group = std::min(kGroup, count - first);
    const std::vector<double>& packed = packed_group(x, first, group, n);
    for (std::size_t k = 0; k < group; ++k) y[first + k]->resize(n);
#pragma omp parallel for schedule(static) if (A.nonzeros() > kParallelNonzeros)
    for (std::size_t i = 0; i < n; ++i) {
      double ax[kGroup];
      row_products(A, i, packed, ax);
      for (std::size_t k = 0; k < group; ++k) (*y[first + k])[i] = ax[k];
    }
  }
}

}  // namespace washout
