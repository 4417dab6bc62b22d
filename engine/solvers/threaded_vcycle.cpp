#include "engine/solvers/threaded_vcycle.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "engine/solvers/row_sum.hpp"

namespace washout {
namespace {

// A coarsest level larger than this is not factorised densely (hypre's coarsest levels hold a
// few rows; one this large means the coarsening stalled).
constexpr std::size_t kMaxDenseRows = 8000;

// A float copy of a borrowed matrix's values, and the view that reads it.
CsrOf<float> rounded(const CsrView& M, std::vector<float>& storage) {
  const auto nnz = static_cast<std::size_t>(M.row_start[M.rows]);
  storage.resize(nnz);
#pragma omp parallel for schedule(static) if (nnz > 100000)
  for (std::size_t k = 0; k < nnz; ++k) storage[k] = static_cast<float>(M.value[k]);
  return {M.rows, M.columns, M.row_start, M.column, storage.data()};
}

}  // namespace

void ThreadedVCycle::build(const std::vector<CsrView>& levels,
                           const std::vector<CsrView>& interpolation, std::size_t block_rows,
                           CyclePrecision precision) {
  if (levels.size() != interpolation.size() + 1 || interpolation.empty())
    throw std::invalid_argument(
        "V-cycle: at least two levels, one interpolation per level below the finest");
  release();  // the previous hierarchy's views and copies
  precision_ = precision;
  exact_.levels = levels;
  exact_.levels[0] = {};  // set_fine()'s
  exact_.interpolation = interpolation;
  block_rows_ = block_rows > 0 ? block_rows : kDefaultBlockRows;
  const std::size_t count = levels.size();
  const std::size_t below = interpolation.size();
  restriction_start_.resize(below);
  restriction_column_.resize(below);
  restriction_value_.resize(below);
  exact_.restriction.resize(below);
  for (std::size_t l = 0; l < below; ++l) {
    // P_l^T by a counting pass over P_l's columns (the coarse rows).
    const CsrView& P = interpolation[l];
    std::vector<int>& start = restriction_start_[l];
    std::vector<int>& column = restriction_column_[l];
    std::vector<double>& value = restriction_value_[l];
    start.assign(P.columns + 1, 0);
    const int nnz = P.row_start[P.rows];
    for (int k = 0; k < nnz; ++k) ++start[P.column[k] + 1];
    for (std::size_t c = 0; c < P.columns; ++c) start[c + 1] += start[c];
    column.resize(nnz);
    value.resize(nnz);
    std::vector<int> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < P.rows; ++i)
      for (int k = P.row_start[i]; k < P.row_start[i + 1]; ++k) {
        const int slot = next[P.column[k]]++;
        column[slot] = static_cast<int>(i);
        value[slot] = P.value[k];
      }
    exact_.restriction[l] = {P.columns, P.rows, start.data(), column.data(), value.data()};
  }
  if (precision_ == CyclePrecision::single_precision) {
    single_levels_.resize(count);
    single_interpolation_.resize(below);
    single_restriction_.resize(below);
    single_.levels.resize(count);
    for (std::size_t l = 1; l < count; ++l)
      single_.levels[l] = rounded(exact_.levels[l], single_levels_[l]);
    for (std::size_t l = 0; l < below; ++l) {
      single_.interpolation.push_back(rounded(exact_.interpolation[l], single_interpolation_[l]));
      single_.restriction.push_back(rounded(exact_.restriction[l], single_restriction_[l]));
    }
  }
  residual_.resize(count);
  coarse_b_.resize(count);
  coarse_x_.resize(count);
  before_.resize(count);
  // Level 0's right-hand side and solution are apply()'s; the coarsest level needs neither a
  // residual nor a sweep's copy.
  for (std::size_t l = 0; l < count; ++l) {
    const std::size_t rows = l == 0 ? interpolation[0].rows : levels[l].rows;
    if (l + 1 < count) {
      residual_[l].resize(rows);
      before_[l].resize(rows);
    }
    if (l > 0) {
      coarse_b_[l].resize(rows);
      coarse_x_[l].resize(rows);
    }
  }
  // The coarsest level by a dense factorisation in double, as hypre's Gaussian elimination
  // there.
  const CsrView& C = levels.back();
  if (C.rows > kMaxDenseRows)
    throw std::runtime_error("V-cycle: coarsest level of " + std::to_string(C.rows) +
                             " rows, too large to factorise densely");
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(C.rows, C.rows);
  for (std::size_t i = 0; i < C.rows; ++i)
    for (int k = C.row_start[i]; k < C.row_start[i + 1]; ++k) dense(i, C.column[k]) += C.value[k];
  coarsest_.compute(dense);
}

void ThreadedVCycle::release() {
  exact_ = {};
  single_ = {};
  for (auto* v : {&restriction_start_, &restriction_column_})
    std::vector<std::vector<int>>().swap(*v);
  for (auto* v : {&restriction_value_, &residual_, &coarse_b_, &coarse_x_, &before_})
    std::vector<std::vector<double>>().swap(*v);
  for (auto* v : {&single_levels_, &single_interpolation_, &single_restriction_})
    std::vector<std::vector<float>>().swap(*v);
  std::vector<float>().swap(single_fine_);
  coarsest_ = {};
}

void ThreadedVCycle::set_fine(const CsrView& fine) {
  if (exact_.interpolation.empty()) throw std::logic_error("V-cycle: set_fine() before build()");
  if (fine.rows != exact_.interpolation[0].rows)
    throw std::invalid_argument("V-cycle: the fine matrix has " + std::to_string(fine.rows) +
                                " rows, the hierarchy " +
                                std::to_string(exact_.interpolation[0].rows));
  exact_.levels[0] = fine;
  if (precision_ == CyclePrecision::single_precision)
    single_.levels[0] = rounded(fine, single_fine_);
}

std::size_t ThreadedVCycle::sweep_blocks(std::size_t rows, std::size_t block_rows) {
  // A multiple of four blocks where there is more than one, so that two or four threads (or
  // eight, sixteen over a larger matrix) take equal shares: 64,000 rows in three blocks kept one
  // of two threads waiting a third of each sweep. The count depends on the rows alone, as it
  // must for a run's numbers not to depend on the threads.
  const std::size_t blocks = std::max<std::size_t>(1, rows / std::max<std::size_t>(1, block_rows));
  return blocks > 1 ? (blocks + 3) / 4 * 4 : 1;
}

template <class Value>
void ThreadedVCycle::sweep(const CsrOf<Value>& A, const double* b, double* x, bool down,
                           std::vector<double>& old) {
  const std::size_t n = A.rows;
  const std::size_t blocks = sweep_blocks(n, block_rows_);
  const auto block_begin = [&](std::size_t blk) { return n * blk / blocks; };
#pragma omp parallel if (blocks > 1)
  {
    // Values outside a row's block come from before the sweep (with one block there are none:
    // plain lexicographic Gauss-Seidel). Going down x starts from zero, so they are zero and
    // each block clears its own rows; coming up each block keeps its rows' values first.
#pragma omp for schedule(static)
    for (std::size_t blk = 0; blk < blocks; ++blk) {
      const std::size_t lo = block_begin(blk), hi = block_begin(blk + 1);
      if (down)
        std::fill(x + lo, x + hi, 0.0);
      else if (blocks > 1)
        std::copy(x + lo, x + hi, old.begin() + static_cast<std::ptrdiff_t>(lo));
    }
#pragma omp for schedule(static)
    for (std::size_t blk = 0; blk < blocks; ++blk) {
      const std::size_t lo = block_begin(blk), hi = block_begin(blk + 1);
      const auto present = [&](int j) {
        const auto c = static_cast<std::size_t>(j);
        return c >= lo && c < hi ? x[c] : down ? 0.0 : old[c];
      };
      const auto relax = [&](std::size_t i) {
        const int first = A.row_start[i];
        const double off =
            sparse_row_sum(A.value, A.column, first + 1, A.row_start[i + 1], present);
        x[i] = (b[i] - off) / A.value[first];
      };
      if (down)
        for (std::size_t i = lo; i < hi; ++i) relax(i);
      else
        for (std::size_t i = hi; i-- > lo;) relax(i);
    }
  }
}

template <class Value>
void ThreadedVCycle::cycle(std::size_t level, const double* b, double* x) {
  const Hierarchy<Value>& H = hierarchy<Value>();
  const CsrOf<Value>& A = H.levels[level];
  const std::size_t n = A.rows;
  if (level + 1 == H.levels.size()) {
    // The coarsest level: solved exactly.
    Eigen::Map<const Eigen::VectorXd> rhs(b, static_cast<Eigen::Index>(n));
    Eigen::Map<Eigen::VectorXd>(x, static_cast<Eigen::Index>(n)) = coarsest_.solve(rhs);
    return;
  }
  sweep(A, b, x, /*down=*/true, before_[level]);  // from x = 0
  // r = b - A x, then b_c = P^T r.
  std::vector<double>& r = residual_[level];
  const bool parallel = n >= 2 * block_rows_;
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = b[i] - sparse_row_dot(A.value, A.column, A.row_start[i], A.row_start[i + 1], x);
  }
  const CsrOf<Value>& R = H.restriction[level];
  const CsrOf<Value>& P = H.interpolation[level];
  std::vector<double>& bc = coarse_b_[level + 1];
  std::vector<double>& xc = coarse_x_[level + 1];
  const std::size_t nc = P.columns;
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t c = 0; c < nc; ++c) {
    double s = 0.0;
    for (int k = R.row_start[c]; k < R.row_start[c + 1]; ++k)
      s += double(R.value[k]) * r[R.column[k]];
    bc[c] = s;
  }
  cycle<Value>(level + 1, bc.data(), xc.data());
  // x += P x_c, then the backward sweep.
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0.0;
    for (int k = P.row_start[i]; k < P.row_start[i + 1]; ++k)
      s += double(P.value[k]) * xc[P.column[k]];
    x[i] += s;
  }
  sweep(A, b, x, /*down=*/false, before_[level]);
}

void ThreadedVCycle::apply(const double* r, double* z) {
  if (exact_.levels.empty() || exact_.levels[0].row_start == nullptr)
    throw std::logic_error("V-cycle: apply() before build() and set_fine()");
  if (precision_ == CyclePrecision::single_precision)
    cycle<float>(0, r, z);
  else
    cycle<double>(0, r, z);
}

}  // namespace washout
