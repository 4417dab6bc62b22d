#include "engine/solvers/sparse_matrix.hpp"

namespace washout {

void CsrMatrix::multiply(const std::vector<double>& x, std::vector<double>& y) const {
  y.resize(rows);
#pragma omp parallel for schedule(static) if (rows > 20000)  // small: not worth a fork
  for (std::size_t i = 0; i < rows; ++i) {
    double s = 0.0;
    for (std::int64_t k = row_start[i]; k < row_start[i + 1]; ++k) s += value[k] * x[column[k]];
    y[i] = s;
  }
}

}  // namespace washout
