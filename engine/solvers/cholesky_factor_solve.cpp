#include "engine/solvers/cholesky_factor_solve.hpp"

#include <algorithm>

namespace washout {

CholeskyFactorSolve::Columns CholeskyFactorSolve::columns() const {
  const auto& L = factor_->matrixL().nestedExpression();  // compressed columns, diagonal first
  return {L.cols(), L.outerIndexPtr(), L.innerIndexPtr(), L.valuePtr()};
}

void CholeskyFactorSolve::build(const Factor& factor) {
  factor_ = &factor;
  const Columns L = columns();

  // Each column's depth in the elimination tree (a parent comes after its children).
  const auto n = static_cast<std::size_t>(L.n);
  std::vector<std::int32_t> depth(n, 0);
  std::int32_t deepest = 0;
  for (std::size_t j = n; j-- > 0;) {
    if (L.start[j + 1] - L.start[j] > 1)
      depth[j] = depth[static_cast<std::size_t>(L.row[L.start[j] + 1])] + 1;
    deepest = std::max(deepest, depth[j]);
  }
  // The columns by depth; within one, longest first, so that a group of four has alike lengths.
  by_depth_.resize(n);
  for (std::size_t j = 0; j < n; ++j) by_depth_[j] = static_cast<std::int32_t>(j);
  const auto length = [&](std::int32_t j) { return L.start[j + 1] - L.start[j]; };
  std::sort(by_depth_.begin(), by_depth_.end(), [&](std::int32_t a, std::int32_t b) {
    const auto da = depth[static_cast<std::size_t>(a)], db = depth[static_cast<std::size_t>(b)];
    if (da != db) return da < db;
    if (length(a) != length(b)) return length(a) > length(b);
    return a < b;
  });
  depth_start_.assign(static_cast<std::size_t>(deepest) + 2, 0);
  for (std::size_t j = 0; j < n; ++j) ++depth_start_[static_cast<std::size_t>(depth[j]) + 1];
  for (std::size_t d = 0; d + 1 < depth_start_.size(); ++d) depth_start_[d + 1] += depth_start_[d];
}

void CholeskyFactorSolve::forward(const Columns& L) {
  double* x = work_.data();
  for (std::int64_t j = 0; j < L.n; ++j) {
    if (x[j] == 0.0) continue;  // subtracts nothing (Eigen skips it too)
    x[j] /= L.value[L.start[j]];
    const double y = x[j];
    for (std::int64_t k = L.start[j] + 1; k < L.start[j + 1]; ++k) x[L.row[k]] -= y * L.value[k];
  }
}

void CholeskyFactorSolve::backward(const Columns& L) {
  double* x = work_.data();
  // x_j = (y_j - sum_{k} L_kj x_k) / L_jj. What a group of four leaves (the tree's top: a chain
  // of long columns, one to a depth) is summed in four partial sums, four chains at once.
  const auto finish = [&](std::int32_t j, std::int64_t from, double sum) {
    const std::int64_t end = L.start[j + 1];
    double s1 = 0.0, s2 = 0.0, s3 = 0.0;
    std::int64_t k = from;
    for (; k + 4 <= end; k += 4) {
      sum -= L.value[k] * x[L.row[k]];
      s1 -= L.value[k + 1] * x[L.row[k + 1]];
      s2 -= L.value[k + 2] * x[L.row[k + 2]];
      s3 -= L.value[k + 3] * x[L.row[k + 3]];
    }
    for (; k < end; ++k) sum -= L.value[k] * x[L.row[k]];
    x[j] = (sum + (s1 + s2 + s3)) / L.value[L.start[j]];
  };
  for (std::size_t d = 0; d + 1 < depth_start_.size(); ++d) {
    std::int64_t g = depth_start_[d];
    const std::int64_t end = depth_start_[d + 1];
    for (; g + 4 <= end; g += 4) {  // four independent columns: four chains at once
      const std::int32_t j0 = by_depth_[g], j1 = by_depth_[g + 1], j2 = by_depth_[g + 2],
                         j3 = by_depth_[g + 3];
      const std::int64_t b0 = L.start[j0] + 1, b1 = L.start[j1] + 1, b2 = L.start[j2] + 1,
                         b3 = L.start[j3] + 1;
      const std::int64_t common = std::min(
          {L.start[j0 + 1] - b0, L.start[j1 + 1] - b1, L.start[j2 + 1] - b2, L.start[j3 + 1] - b3});
      double s0 = x[j0], s1 = x[j1], s2 = x[j2], s3 = x[j3];
      for (std::int64_t k = 0; k < common; ++k) {
        s0 -= L.value[b0 + k] * x[L.row[b0 + k]];
        s1 -= L.value[b1 + k] * x[L.row[b1 + k]];
        s2 -= L.value[b2 + k] * x[L.row[b2 + k]];
        s3 -= L.value[b3 + k] * x[L.row[b3 + k]];
      }
      finish(j0, b0 + common, s0);
      finish(j1, b1 + common, s1);
      finish(j2, b2 + common, s2);
      finish(j3, b3 + common, s3);
    }
    for (; g < end; ++g) finish(by_depth_[g], L.start[by_depth_[g]] + 1, x[by_depth_[g]]);
  }
}

void CholeskyFactorSolve::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const Columns L = columns();
  work_ = factor_->permutationP() * b;
  forward(L);
  backward(L);
  x = factor_->permutationPinv() * work_;
}

}  // namespace washout
