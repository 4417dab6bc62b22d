#pragma once
// A square sparse matrix in compressed rows (CSR). The pressure Poisson matrix is symmetric,
// so its rows are also its columns (CSC) and can be handed to CHOLMOD without a transpose.
#include <cstdint>
#include <vector>

namespace washout {

struct CsrMatrix {
  std::size_t rows = 0;
  std::vector<std::int64_t> row_start;  // [rows + 1]
  std::vector<std::int32_t> column;
  std::vector<double> value;

  std::size_t nonzeros() const { return value.size(); }
  void multiply(const std::vector<double>& x, std::vector<double>& y) const;  // y = A x
};

// y[k] = A x[k] for several vectors in one read of the matrix (full rows, the vectors side by
// side: the body coupling's responses iterated together, pcg_solver.cpp).
void multiply_many(const CsrMatrix& A, const std::vector<const std::vector<double>*>& x,
                   const std::vector<std::vector<double>*>& y);

}  // namespace washout
