#pragma once
// The two triangular solves of a sparse Cholesky factor (Eigen's SimplicialLLT, L L^T = P A P^T),
// faster than the factor's own solve and equal to it to rounding.
//
// Eigen solves column by column through the row indices, one dependent multiply-add after
// another. Here the columns are grouped into supernodes: runs of consecutive columns j..e-1 in
// which each column's rows are the next column's plus that column itself, so that the run shares
// one list of rows below its diagonal block (the factor of a 3D coarse PPE system holds about
// 70 % of its entries in supernodes eight or more columns wide). Below the diagonal block a
// supernode is a dense block of rows, whose x are gathered once: the forward solve subtracts
// four columns' products from them a pass, the backward solve takes four columns' dot products
// with them a pass (contiguous, vectorised, four independent sums). The diagonal block goes the
// same way in panels of four columns, each panel's own small triangle solved in between.
// Another rounding than Eigen's (tests/unit/test_cholesky_factor_solve.cpp holds it to Eigen's
// solve).
// Used for the coarse system of pcg_agg (aggregation_preconditioner.cpp), where it is serial
// work inside every CG iteration (docs/performance.md, forty-second session).
#include <Eigen/SparseCholesky>
#include <cstdint>
#include <vector>

namespace washout {

class CholeskyFactorSolve {
 public:
  using Factor = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower>;

  // Finds the factor's supernodes. The solves read the factor's arrays in place: keep it alive,
  // and call again after each compute() of it.
  void build(const Factor& factor);

  // x = A^-1 b with the factor given to build().
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  std::size_t rows() const { return factor_ ? static_cast<std::size_t>(factor_->rows()) : 0; }
  std::size_t supernodes() const { return node_start_.empty() ? 0 : node_start_.size() - 1; }
  // The widest supernode's columns.
  std::size_t widest_supernode() const;

 private:
  // L by columns, in the factor's own arrays: the diagonal first, rows increasing.
  struct Columns {
    std::int64_t n;
    const int *start, *row;
    const double* value;
  };
  // Column j's entries from `offset` places below its diagonal on: rows j + 1..e - 1 of its
  // supernode's diagonal block (e its end) come first, then the rows below the block.
  static const double* entries_from(const Columns& L, std::int64_t j, std::int64_t offset) {
    return L.value + L.start[j] + offset;
  }
  Columns columns() const;
  void forward(const Columns& L);   // L y = b in place
  void backward(const Columns& L);  // L^T x = y in place

  const Factor* factor_ = nullptr;
  std::vector<std::int32_t> node_start_;  // supernode k: columns node_start_[k] to [k + 1] - 1
  Eigen::VectorXd work_;
  std::vector<double> inverse_diagonal_;  // 1 / L_jj
  std::vector<double> below_;  // x in the rows below one supernode's diagonal block, gathered
};

}  // namespace washout
