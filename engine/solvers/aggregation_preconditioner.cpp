// Two-level preconditioner for the PPE matrix: Jacobi plus a coarse correction on aggregates of
// neighbouring particles,
//   M^-1 r = D^-1 r + P A_c^-1 P^T r,   A_c = P^T A P,
// P the piecewise-constant prolongation (P_iI = 1 when row i belongs to aggregate I). Jacobi
// damps the short waves in a few iterations; the long ones, which make Jacobi CG's iterations
// grow as 1/d0, are what the coarse system solves directly. The additive form keeps M symmetric
// positive definite (the sum of one such matrix and a semidefinite one), as CG needs.
//
// The aggregates come from the matrix alone: a row's strong neighbours are those coupled by at
// least kStrength times its largest off-diagonal entry; the PPE's laplacian weight falls with
// distance, so these are the particles nearest to it. Greedy, in row order (Vanek, Mandel &
// Brezina 1996, phases 1-3): a row whose strong neighbours are all free founds an aggregate with
// them; a row left over joins the aggregate it is most strongly coupled to; a row coupled to
// none founds its own with its free neighbours. A row whose only entry is its diagonal (a given
// pressure) belongs to none: Jacobi solves it exactly. The rows are taken in fixed blocks that
// aggregate on their own, so that the set-up runs on all threads and does not depend on their
// number (the fluid is sorted by cell, so a block of rows is a compact piece of the flow).
// The coarse system is factorised (Eigen's simplicial Cholesky; solved by
// cholesky_factor_solve.hpp): its size grows as the fine one's, so this is a solver for the sizes
// below BoomerAMG's (docs/performance.md).
#include <omp.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/solvers/cholesky_factor_solve.hpp"
#include "engine/solvers/preconditioner.hpp"
#include "engine/solvers/solver_counters.hpp"

namespace washout {
namespace {

// Measured on saved 3D systems (8,000 and 14,000 unknowns, docs/performance.md): 0.5 gave
// aggregates of about 8 rows and 17 iterations, 0.2 about 20 rows and 19-20 iterations with a
// coarse factor a sixth the size, 0.1 about 27 rows and 21-22 iterations.
constexpr double kStrength = 0.2;
constexpr std::size_t kBlockRows = 2048;  // rows aggregated together
// A set-up serves this many new matrices, sooner renewed when a solve takes more than
// kStaleGrowth times the first one's iterations (plus two), as BoomerAMG's (hypre_amg.cpp). Same-
// case 3D dam break a/20 (docs/performance.md): a set-up every solve 2.05 s of PPE solve, every
// 5, 10 and 20 solves 1.35, 1.28 and 1.54 s, about 23 iterations a step either way.
constexpr int kReuseSolves = 10;
constexpr double kStaleGrowth = 1.5;
constexpr std::size_t kParallelRows = 4096;  // below this, one thread (as pcg_solver.cpp)
constexpr std::int32_t kFree = -1, kNone = -2;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class AggregationPreconditioner final : public Preconditioner {
 public:
  void prepare(const CsrMatrix& A, bool same_matrix) override {
    if (same_matrix && rows_ == A.rows) return;
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    // The aggregates and the coarse factor serve kReuseSolves matrices of one size (the rows are
    // the fluid particles, numbered alike from step to step, simulation.cpp); the diagonal (the
    // Jacobi preconditioner's) is each matrix's own. M stays symmetric positive definite whatever A
    // it was built from.
    const bool reuse = rows_ == A.rows && uses_ < kReuseSolves && !stale_;
    jacobi_->prepare(A, false);
    auto& counters = solver_counters();
    if (!reuse) {
      take_strength(A);
      aggregate(A);
      build_coarse(A);
      factor_coarse();
      rows_ = A.rows;
      uses_ = 0;
      fresh_iterations_ = -1;
      stale_ = false;
      ++counters.setups;
    }
    ++uses_;
    counters.setup_seconds += seconds_since(start);
    counters.setup_cpu_seconds += thread_cpu_seconds() - cpu_start;
    const double bytes = double(A.rows) * (2 * sizeof(double) + sizeof(std::int32_t)) +
                         double(factor_nonzeros_) * (sizeof(double) + sizeof(int));
    counters.setup_bytes = std::max(counters.setup_bytes, bytes);
  }

  void solved(int iterations) override {
    if (fresh_iterations_ < 0)
      fresh_iterations_ = iterations;
    else if (iterations > kStaleGrowth * fresh_iterations_ + 2)
      stale_ = true;  // the flow has moved on from the aggregates: a new set-up next time
  }

  void apply(const std::vector<double>& r, std::vector<double>& z) override {
    const std::size_t n = r.size();
    const bool parallel = n > kParallelRows;
    const std::vector<double>& inverse_diagonal = *jacobi_->inverse_diagonal();
    z.resize(n);
    const auto m = static_cast<std::int64_t>(coarse_rows_);
    if (m > 0) {
      // P^T r, each aggregate summing its own members (the same order on any thread count).
      coarse_rhs_.resize(m);
#pragma omp parallel for schedule(static) if (parallel)
      for (std::int64_t c = 0; c < m; ++c) {
        double sum = 0.0;
        for (std::int32_t e = member_start_[c]; e < member_start_[c + 1]; ++e) sum += r[member_[e]];
        coarse_rhs_[c] = sum;
      }
      coarse_solve_.solve(coarse_rhs_, coarse_solution_);
    }
#pragma omp parallel for schedule(static) if (parallel)
    for (std::size_t i = 0; i < n; ++i) {
      const std::int32_t c = aggregate_of_[i];
      z[i] = inverse_diagonal[i] * r[i] + (c >= 0 ? coarse_solution_[c] : 0.0);
    }
  }

 private:
  // The strength threshold of each row: kStrength times its largest off-diagonal magnitude (0 for
  // a row coupled to nothing). Needed by the aggregation only, so at a set-up only.
  void take_strength(const CsrMatrix& A) {
    const std::size_t n = A.rows;
    threshold_.assign(n, 0.0);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) {
      double largest = 0.0;
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k)
        if (static_cast<std::size_t>(A.column[k]) != i)
          largest = std::max(largest, std::abs(A.value[k]));
      threshold_[i] = kStrength * largest;
    }
  }

  // Phases 1-3 within each block of rows; aggregates are numbered within their block first.
  void aggregate(const CsrMatrix& A) {
    const std::size_t n = A.rows;
    const std::size_t blocks = (n + kBlockRows - 1) / kBlockRows;
    aggregate_of_.assign(n, kFree);
    std::vector<std::int32_t> block_count(blocks + 1, 0);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t b = 0; b < blocks; ++b)
      block_count[b + 1] = aggregate_block(A, b * kBlockRows, std::min(n, (b + 1) * kBlockRows));
    for (std::size_t b = 0; b < blocks; ++b) block_count[b + 1] += block_count[b];
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) {
      std::int32_t& c = aggregate_of_[i];
      c = c == kNone ? -1 : c + block_count[i / kBlockRows];
    }
    coarse_rows_ = static_cast<std::size_t>(block_count[blocks]);

    // Each aggregate's members, in row order.
    const std::size_t m = coarse_rows_;
    member_start_.assign(m + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
      if (aggregate_of_[i] >= 0) ++member_start_[aggregate_of_[i] + 1];
    for (std::size_t c = 0; c < m; ++c) member_start_[c + 1] += member_start_[c];
    member_.resize(static_cast<std::size_t>(member_start_[m]));
    std::vector<std::int32_t> fill(member_start_.begin(), member_start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      if (aggregate_of_[i] >= 0) member_[fill[aggregate_of_[i]]++] = static_cast<std::int32_t>(i);
  }

  // Aggregates rows [first, end) among themselves (neighbours outside count as taken); returns
  // how many aggregates it made, numbered from 0 in aggregate_of_.
  std::int32_t aggregate_block(const CsrMatrix& A, std::size_t first, std::size_t end) {
    const auto inside = [&](std::int32_t j) {
      return static_cast<std::size_t>(j) >= first && static_cast<std::size_t>(j) < end;
    };
    const auto strong = [&](std::size_t i, std::int64_t k) {
      return static_cast<std::size_t>(A.column[k]) != i && std::abs(A.value[k]) >= threshold_[i];
    };
    std::int32_t count = 0;
    // Phase 1: roots whose strong neighbourhood is all free (and in the block).
    for (std::size_t i = first; i < end; ++i) {
      if (threshold_[i] == 0.0) {
        aggregate_of_[i] = kNone;
        continue;
      }
      if (aggregate_of_[i] != kFree) continue;
      bool all_free = true;
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1] && all_free; ++k)
        if (strong(i, k)) all_free = inside(A.column[k]) && aggregate_of_[A.column[k]] == kFree;
      if (!all_free) continue;
      aggregate_of_[i] = count;
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k)
        if (strong(i, k)) aggregate_of_[A.column[k]] = count;
      ++count;
    }
    // Phase 2: a free row joins the phase-1 aggregate it is most strongly coupled to (so that an
    // aggregate grows by one ring at most: the choices are made before any is applied).
    std::vector<std::int32_t> joined(aggregate_of_.begin() + static_cast<std::ptrdiff_t>(first),
                                     aggregate_of_.begin() + static_cast<std::ptrdiff_t>(end));
    for (std::size_t i = first; i < end; ++i) {
      if (aggregate_of_[i] != kFree) continue;
      double best = 0.0;
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k) {
        const std::int32_t j = A.column[k];
        if (!inside(j) || static_cast<std::size_t>(j) == i || aggregate_of_[j] < 0) continue;
        if (std::abs(A.value[k]) > best) {
          best = std::abs(A.value[k]);
          joined[i - first] = aggregate_of_[j];
        }
      }
    }
    std::copy(joined.begin(), joined.end(),
              aggregate_of_.begin() + static_cast<std::ptrdiff_t>(first));
    // Phase 3: rows coupled to no aggregate found their own with their free neighbours.
    for (std::size_t i = first; i < end; ++i) {
      if (aggregate_of_[i] != kFree) continue;
      aggregate_of_[i] = count;
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k)
        if (inside(A.column[k]) && aggregate_of_[A.column[k]] == kFree)
          aggregate_of_[A.column[k]] = count;
      ++count;
    }
    return count;
  }

  // A_c = P^T A P: each entry a_ij added to (aggregate of i, aggregate of j). Its lower triangle
  // in compressed columns, a column (an aggregate) at a time from its members' rows; each thread
  // fills the columns of its share into buffers of its own, joined in column order.
  void build_coarse(const CsrMatrix& A) {
    const std::size_t m = coarse_rows_;
    if (m == 0) return;
    const bool parallel = A.rows > kParallelRows;
#pragma omp parallel if (parallel)
    {
#pragma omp single
      parts_.resize(static_cast<std::size_t>(omp_get_num_threads()));
      Part& part = parts_[static_cast<std::size_t>(omp_get_thread_num())];
      part.column_end.clear();
      part.row.clear();
      part.value.clear();
      part.slot.assign(m, -1);
      std::vector<std::pair<int, double>> column;
#pragma omp for schedule(static)
      for (std::size_t I = 0; I < m; ++I) {
        const std::size_t first = part.row.size();
        for (std::int32_t e = member_start_[I]; e < member_start_[I + 1]; ++e) {
          const auto i = static_cast<std::size_t>(member_[e]);
          for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k) {
            const std::int32_t J = aggregate_of_[A.column[k]];
            if (J < 0) continue;
            if (part.slot[J] < 0) {
              part.slot[J] = static_cast<std::int32_t>(part.row.size());
              part.row.push_back(J);
              part.value.push_back(0.0);
            }
            part.value[part.slot[J]] += A.value[k];
          }
        }
        // The lower triangle's rows (J >= I), in increasing order as compressed storage wants.
        column.clear();
        for (std::size_t e = first; e < part.row.size(); ++e) {
          part.slot[part.row[e]] = -1;
          if (part.row[e] >= static_cast<int>(I)) column.emplace_back(part.row[e], part.value[e]);
        }
        std::sort(column.begin(), column.end());
        part.row.resize(first + column.size());
        part.value.resize(first + column.size());
        for (std::size_t e = 0; e < column.size(); ++e) {
          part.row[first + e] = column[e].first;
          part.value[first + e] = column[e].second;
        }
        part.column_end.push_back(static_cast<int>(part.row.size()));
      }
    }
    outer_.assign(1, 0);
    inner_.clear();
    values_.clear();
    for (const Part& part : parts_) {  // the threads' shares are consecutive columns, in order
      const int base = static_cast<int>(inner_.size());
      for (const int end : part.column_end) outer_.push_back(base + end);
      inner_.insert(inner_.end(), part.row.begin(), part.row.end());
      values_.insert(values_.end(), part.value.begin(), part.value.end());
    }
    const auto size = static_cast<Eigen::Index>(m);
    coarse_ = Eigen::Map<const Eigen::SparseMatrix<double>>(
        size, size, static_cast<Eigen::Index>(inner_.size()), outer_.data(), inner_.data(),
        values_.data());
  }

  void factor_coarse() {
    if (coarse_rows_ == 0) return;
    coarse_factor_.compute(coarse_);
    if (coarse_factor_.info() != Eigen::Success)
      throw SolverError("the pressure solve's coarse system (aggregates) is not positive definite");
    factor_nonzeros_ =
        static_cast<std::size_t>(coarse_factor_.matrixL().nestedExpression().nonZeros());
    coarse_solve_.build(coarse_factor_);
  }

  struct Part {  // one thread's columns of the coarse matrix
    std::vector<int> column_end, row;
    std::vector<double> value;
    std::vector<std::int32_t> slot;  // where each coarse row sits in the column being filled
  };

  std::unique_ptr<Preconditioner> jacobi_ = make_jacobi_preconditioner();  // D^-1, each matrix's
  std::vector<double> threshold_;
  std::vector<std::int32_t> aggregate_of_, member_start_, member_;
  std::size_t coarse_rows_ = 0, factor_nonzeros_ = 0, rows_ = 0;
  int uses_ = 0, fresh_iterations_ = -1;
  bool stale_ = false;
  std::vector<Part> parts_;
  std::vector<int> outer_, inner_;
  std::vector<double> values_;
  Eigen::SparseMatrix<double> coarse_;
  CholeskyFactorSolve::Factor coarse_factor_;
  CholeskyFactorSolve coarse_solve_;  // the factor's solves, their chains interleaved
  Eigen::VectorXd coarse_rhs_, coarse_solution_;
};

}  // namespace

std::unique_ptr<Preconditioner> make_aggregation_preconditioner() {
  return std::make_unique<AggregationPreconditioner>();
}

}  // namespace washout
