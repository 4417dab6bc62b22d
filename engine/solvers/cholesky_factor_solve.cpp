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
  // Column j + 1 continues column j's supernode when column j's rows are j, j + 1 and then
  // exactly column j + 1's rows below its diagonal: by induction every column of a supernode
  // j..e-1 holds the rows from itself to e - 1 and then the last column's rows below.
  const auto continues = [&](std::int64_t j) {
    const std::int64_t a = L.start[j], b = L.start[j + 1];
    if (b - a != L.start[j + 2] - b + 1 || L.row[a + 1] != j + 1) return false;
    return std::equal(L.row + a + 2, L.row + b, L.row + b + 1);
  };
  node_start_.assign(1, 0);
  std::size_t longest = 0;  // no supernode has more rows below it than the longest column
  for (std::int64_t j = 0; j < L.n; ++j) {
    longest = std::max(longest, static_cast<std::size_t>(L.start[j + 1] - L.start[j]));
    if (j + 1 == L.n || !continues(j)) node_start_.push_back(static_cast<std::int32_t>(j + 1));
  }
  below_.resize(longest);
  // Multiplied by, not divided: the solves' chains wait for each column's result, and a
  // division takes several times a multiplication's latency.
  inverse_diagonal_.resize(static_cast<std::size_t>(L.n));
  for (std::int64_t j = 0; j < L.n; ++j) inverse_diagonal_[j] = 1.0 / L.value[L.start[j]];
}

std::size_t CholeskyFactorSolve::widest_supernode() const {
  std::size_t widest = 0;
  for (std::size_t k = 0; k + 1 < node_start_.size(); ++k)
    widest = std::max(widest, static_cast<std::size_t>(node_start_[k + 1] - node_start_[k]));
  return widest;
}

namespace {

constexpr std::int64_t kPanel = 4;  // columns taken together in the dense blocks

// out[r] -= sum_c column[c][r] y[c] over `count` (<= kPanel) columns: four columns a pass, so
// that each load and store of out serves four products.
void subtract_columns(const double* const* column, const double* y, std::int64_t count, double* out,
                      std::int64_t length) {
  if (count == kPanel) {
    const double *c0 = column[0], *c1 = column[1], *c2 = column[2], *c3 = column[3];
    const double y0 = y[0], y1 = y[1], y2 = y[2], y3 = y[3];
#pragma omp simd
    for (std::int64_t r = 0; r < length; ++r)
      out[r] -= (c0[r] * y0 + c1[r] * y1) + (c2[r] * y2 + c3[r] * y3);
    return;
  }
  for (std::int64_t c = 0; c < count; ++c) {
    const double* cc = column[c];
    const double yc = y[c];
#pragma omp simd
    for (std::int64_t r = 0; r < length; ++r) out[r] -= cc[r] * yc;
  }
}

// dot[c] = sum_r column[c][r] v[r] over `count` (<= kPanel) columns: four independent sums
// sharing each load of v.
void dot_columns(const double* const* column, std::int64_t count, const double* v,
                 std::int64_t length, double* dot) {
  if (count == kPanel) {
    const double *c0 = column[0], *c1 = column[1], *c2 = column[2], *c3 = column[3];
    double d0 = 0.0, d1 = 0.0, d2 = 0.0, d3 = 0.0;
#pragma omp simd reduction(+ : d0, d1, d2, d3)
    for (std::int64_t r = 0; r < length; ++r) {
      const double g = v[r];
      d0 += c0[r] * g;
      d1 += c1[r] * g;
      d2 += c2[r] * g;
      d3 += c3[r] * g;
    }
    dot[0] = d0, dot[1] = d1, dot[2] = d2, dot[3] = d3;
    return;
  }
  for (std::int64_t c = 0; c < count; ++c) {
    const double* cc = column[c];
    double d = 0.0;
#pragma omp simd reduction(+ : d)
    for (std::int64_t r = 0; r < length; ++r) d += cc[r] * v[r];
    dot[c] = d;
  }
}

}  // namespace

// L y = b, a supernode at a time and within it a panel of kPanel columns at a time: the panel's
// own small triangle, then its columns subtracted from the block's later rows and from the rows
// below the block (gathered, updated, scattered back).
void CholeskyFactorSolve::forward(const Columns& L) {
  double* x = work_.data();
  const double* column[kPanel];
  for (std::size_t k = 0; k + 1 < node_start_.size(); ++k) {
    const std::int64_t s = node_start_[k], e = node_start_[k + 1];
    const std::int64_t below = L.start[e] - L.start[e - 1] - 1;
    const int* rows = L.row + L.start[e - 1] + 1;
    double* gathered = below_.data();
    for (std::int64_t r = 0; r < below; ++r) gathered[r] = x[rows[r]];
    for (std::int64_t ps = s; ps < e; ps += kPanel) {
      const std::int64_t pe = std::min(ps + kPanel, e), count = pe - ps;
      for (std::int64_t j = ps; j < pe; ++j) {
        const double* diagonal = entries_from(L, j, 0);
        x[j] *= inverse_diagonal_[j];
        for (std::int64_t i = j + 1; i < pe; ++i) x[i] -= x[j] * diagonal[i - j];
      }
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, pe - ps - c);
      subtract_columns(column, x + ps, count, x + pe, e - pe);
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, e - ps - c);
      subtract_columns(column, x + ps, count, gathered, below);
    }
    for (std::int64_t r = 0; r < below; ++r) x[rows[r]] = gathered[r];
  }
}

// L^T x = y, the supernodes from the last: the rows below a supernode are final, their x
// gathered once and dotted with its columns; then its diagonal block a panel at a time from
// its last column, the rows after the panel dotted with the panel's columns before the panel's
// small triangle.
void CholeskyFactorSolve::backward(const Columns& L) {
  double* x = work_.data();
  const double* column[kPanel];
  double dot[kPanel];
  for (std::size_t k = node_start_.size() - 1; k-- > 0;) {
    const std::int64_t s = node_start_[k], e = node_start_[k + 1];
    const std::int64_t below = L.start[e] - L.start[e - 1] - 1;
    const int* rows = L.row + L.start[e - 1] + 1;
    double* gathered = below_.data();
    for (std::int64_t r = 0; r < below; ++r) gathered[r] = x[rows[r]];
    for (std::int64_t pe = e; pe > s;) {
      const std::int64_t ps = std::max(pe - kPanel, s), count = pe - ps;
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, e - ps - c);
      dot_columns(column, count, gathered, below, dot);
      for (std::int64_t c = 0; c < count; ++c) x[ps + c] -= dot[c];
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, pe - ps - c);
      dot_columns(column, count, x + pe, e - pe, dot);
      for (std::int64_t c = 0; c < count; ++c) x[ps + c] -= dot[c];
      for (std::int64_t j = pe - 1; j >= ps; --j) {
        const double* diagonal = entries_from(L, j, 0);
        double sum = x[j];
        for (std::int64_t i = j + 1; i < pe; ++i) sum -= diagonal[i - j] * x[i];
        x[j] = sum * inverse_diagonal_[j];
      }
      pe = ps;
    }
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
