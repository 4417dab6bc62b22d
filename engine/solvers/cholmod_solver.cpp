// Direct sparse Cholesky factorisation with SuiteSparse CHOLMOD (simplicial LL', AMD ordering).
// The sparsity changes every step as neighbours change, so each solve analyses and factorises;
// the factor is kept for further right-hand sides (solve_again).
#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <cstring>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/solver_counters.hpp"

namespace washout {
namespace {

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    cholmod_l_start(&common_);
    common_.print = 0;
    // Simplicial, not supernodal: on the 2D pressure systems (up to 60,000 unknowns) the
    // supernodal factor's dense blocks are small, so it gains nothing from the BLAS, and its own
    // OpenMP loops fight the run's: it was 1.3x (one thread) to 1.75x (two) slower with Debian's
    // reference BLAS, 2.2x on two threads with OpenBLAS-OpenMP (docs/performance.md, thirteenth
    // session). LL', not LDL': a simplicial LDL' takes an indefinite matrix without a word, LL'
    // stops at its first non-positive pivot (the check in solve()).
    common_.supernodal = CHOLMOD_SIMPLICIAL;
    common_.final_ll = 1;
  }
  ~CholmodSolver() override {
    release();
    cholmod_l_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;
  std::string name() const override { return "cholmod"; }
  bool direct() const override { return true; }

  SolveReport solve(const CsrMatrix& A, const std::vector<double>& b,
                    std::vector<double>& x) override {
    release();
    const std::size_t n = A.rows;
    x.assign(n, 0.0);
    if (n == 0) return {};
    // Symmetric: the CSR rows are the CSC columns; stype = 1 reads the upper triangle
    // (entries with row <= column), which in our storage are the columns >= row of each row.
    cholmod_sparse* M =
        cholmod_l_allocate_sparse(n, n, A.nonzeros(), 0, 1, 1, CHOLMOD_REAL, &common_);
    auto* p = static_cast<SuiteSparse_long*>(M->p);
    auto* idx = static_cast<SuiteSparse_long*>(M->i);
    auto* val = static_cast<double*>(M->x);
    for (std::size_t c = 0; c <= n; ++c) p[c] = A.row_start[c];
    for (std::size_t k = 0; k < A.nonzeros(); ++k) {
      idx[k] = A.column[k];
      val[k] = A.value[k];
    }
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    factor_ = cholmod_l_analyze(M, &common_);
    cholmod_l_factorize(M, factor_, &common_);
    auto& counters = solver_counters();
    ++counters.setups;
    counters.setup_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    counters.setup_cpu_seconds += thread_cpu_seconds() - cpu_start;
    // The factor's non-zeros, each a value and a row index.
    counters.setup_bytes = std::max(
        counters.setup_bytes, common_.lnz * double(sizeof(double) + sizeof(SuiteSparse_long)));
    const bool positive = common_.status == CHOLMOD_OK && factor_->minor >= n;
    cholmod_l_free_sparse(&M, &common_);
    if (!positive) {
      release();
      throw SolverError("CHOLMOD: the pressure matrix is not positive definite");
    }
    return substitute(A, b, x);
  }

  SolveReport solve_again(const CsrMatrix& A, const std::vector<double>& b,
                          std::vector<double>& x) override {
    if (!factor_ || factor_->n != A.rows) return solve(A, b, x);
    return substitute(A, b, x);
  }

 private:
  SolveReport substitute(const CsrMatrix& A, const std::vector<double>& b, std::vector<double>& x) {
    const std::size_t n = A.rows;
    x.assign(n, 0.0);
    cholmod_dense* B = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &common_);
    std::memcpy(B->x, b.data(), n * sizeof(double));
    cholmod_dense* X = cholmod_l_solve(CHOLMOD_A, factor_, B, &common_);
    std::memcpy(x.data(), X->x, n * sizeof(double));
    cholmod_l_free_dense(&X, &common_);
    cholmod_l_free_dense(&B, &common_);
    SolveReport report;
    report.iterations = 1;
    report.relative_residual = relative_residual(A, b, x);
    return report;
  }

  void release() {
    if (factor_) cholmod_l_free_factor(&factor_, &common_);
  }

  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace washout
