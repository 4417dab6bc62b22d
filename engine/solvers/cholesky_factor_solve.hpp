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
//
// Two threads. A column's entries below its diagonal lie in the rows of its ancestors in the
// elimination tree (parent(j): the first row below L_jj), so two disjoint subtrees are solved
// independently, forwards and backwards, except where they meet in their common ancestors. The
// tree is cut into a top (the ancestors) and subtrees shared between two groups of about equal
// work; forwards, each group solves its subtrees and sums what it subtracts from the top's rows
// in a vector of its own, the two added in group order before the top is solved; backwards, the
// top first, then the groups. The groups are a property of the factor, not of the threads: one
// thread solves both, one after the other, to the same bits.
// Used for the coarse system of pcg_agg (aggregation_preconditioner.cpp), where it is serial
// work inside every CG iteration (docs/performance.md, forty-second and forty-third sessions).
#include <Eigen/SparseCholesky>
#include <array>
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
  // The factor's entries in each group's subtrees and in the top (all in the top where no cut
  // pays: a small factor, or a tree without two subtrees of comparable work).
  std::array<std::size_t, 2> group_entries() const { return group_entries_; }
  std::size_t top_entries() const { return top_entries_; }

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
  // Each column's owner: group 0 or 1, or kTop; fills group_entries_ and top_entries_.
  std::vector<std::int8_t> cut_tree(const Columns& L);
  // L y = b in place over the supernodes `nodes` (increasing); the rows below a supernode past
  // its first own_below_[k] (the top's, for a group's supernode) are updated in `top_part`.
  void forward(const Columns& L, const std::vector<std::int32_t>& nodes, double* top_part,
               double* gathered);
  // L^T x = y in place over `nodes`, taken from the last.
  void backward(const Columns& L, const std::vector<std::int32_t>& nodes, double* gathered);

  static constexpr std::int8_t kTop = -1;
  const Factor* factor_ = nullptr;
  std::vector<std::int32_t> node_start_;  // supernode k: columns node_start_[k] to [k + 1] - 1
  std::vector<std::int64_t> own_below_;   // per supernode: its rows below in its own group
  std::array<std::vector<std::int32_t>, 2> group_nodes_;  // supernodes of each group
  std::vector<std::int32_t> top_nodes_;
  std::array<std::size_t, 2> group_entries_{};
  std::size_t top_entries_ = 0;
  bool parallel_ = false;  // the groups on two threads
  Eigen::VectorXd work_;
  std::vector<double> inverse_diagonal_;  // 1 / L_jj
  // Per group: its forward solve's updates of the top's rows (zero elsewhere), and x in the rows
  // below one supernode's diagonal block, gathered (the top uses group 0's).
  std::array<std::vector<double>, 2> top_part_, below_;
};

}  // namespace washout
