#pragma once
// The two triangular solves of a sparse Cholesky factor (Eigen's SimplicialLLT, L L^T = P A P^T),
// faster than the factor's own solve and equal to it to rounding.
//
// Eigen solves L^T x = y column by column, x_j = (y_j - sum_{i > j} L_ij x_i) / L_jj, each sum
// one chain of dependent multiply-adds: a product waits for the one before it (about four
// cycles each), however many independent columns there are. Column j needs the x_i of its
// ancestors in the elimination tree (parent(j) = the first row under the diagonal of column j),
// so the columns at one depth of the tree are independent; here they are taken four at a time,
// their four chains interleaved, each sum in Eigen's order. The tree's top, a chain of long
// columns one to a depth, has nothing to interleave: each of its sums is split into four partial
// sums (another rounding; tests/unit/test_cholesky_factor_solve.cpp holds it to Eigen's solve).
// L y = b is Eigen's own loop: there each column subtracts its products from the rows below it,
// no chain of sums.
// Used for the coarse system of pcg_agg (aggregation_preconditioner.cpp): 0.65 -> 0.53 ms a solve
// at 3,429 aggregates with the interleaving alone, where it took a third of each iteration
// (docs/performance.md, thirty-sixth and thirty-seventh sessions).
#include <Eigen/SparseCholesky>
#include <cstdint>
#include <vector>

namespace washout {

class CholeskyFactorSolve {
 public:
  using Factor = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower>;

  // Orders L^T's columns by depth in the factor's tree. The solves read the factor's arrays in
  // place: keep it alive, and call again after each compute() of it.
  void build(const Factor& factor);

  // x = A^-1 b with the factor given to build().
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  std::size_t rows() const { return factor_ ? static_cast<std::size_t>(factor_->rows()) : 0; }
  // The depths of the tree: the longest chain of columns that must wait for each other.
  std::size_t depths() const { return depth_start_.empty() ? 0 : depth_start_.size() - 1; }

 private:
  // L by columns, in the factor's own arrays: the diagonal first, rows increasing.
  struct Columns {
    std::int64_t n;
    const int *start, *row;
    const double* value;
  };
  Columns columns() const;
  void forward(const Columns& L);   // L y = b in place, Eigen's loop
  void backward(const Columns& L);  // L^T x = y in place, the columns of each depth four at a time

  const Factor* factor_ = nullptr;
  std::vector<std::int32_t> by_depth_;     // the columns, depth by depth from the root
  std::vector<std::int64_t> depth_start_;  // where each depth begins in by_depth_
  Eigen::VectorXd work_;
};

}  // namespace washout
