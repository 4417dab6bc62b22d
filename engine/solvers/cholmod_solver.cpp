// Direct sparse Cholesky factorisation with SuiteSparse CHOLMOD (supernodal, AMD ordering).
// The sparsity changes every step as neighbours change, so each solve analyses and factorises.
#include <cholmod.h>

#include <cstring>

#include "engine/solvers/linear_solver.hpp"

namespace washout {
namespace {

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() { cholmod_l_start(&common_); common_.print = 0; }
  ~CholmodSolver() override { cholmod_l_finish(&common_); }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;
  std::string name() const override { return "cholmod"; }

  SolveReport solve(const CsrMatrix& A, const std::vector<double>& b,
                    std::vector<double>& x) override {
    const std::size_t n = A.rows;
    x.assign(n, 0.0);
    if (n == 0) return {};
    // Symmetric: the CSR rows are the CSC columns; stype = 1 reads the upper triangle
    // (entries with row <= column), which in our storage are the columns >= row of each row.
    cholmod_sparse* M = cholmod_l_allocate_sparse(n, n, A.nonzeros(), 0, 1, 1, CHOLMOD_REAL,
                                                  &common_);
    auto* p = static_cast<SuiteSparse_long*>(M->p);
    auto* idx = static_cast<SuiteSparse_long*>(M->i);
    auto* val = static_cast<double*>(M->x);
    for (std::size_t c = 0; c <= n; ++c) p[c] = A.row_start[c];
    for (std::size_t k = 0; k < A.nonzeros(); ++k) {
      idx[k] = A.column[k];
      val[k] = A.value[k];
    }
    cholmod_factor* L = cholmod_l_analyze(M, &common_);
    cholmod_l_factorize(M, L, &common_);
    if (common_.status != CHOLMOD_OK || L->minor < n) {
      cholmod_l_free_factor(&L, &common_);
      cholmod_l_free_sparse(&M, &common_);
      throw SolverError("CHOLMOD: the pressure matrix is not positive definite");
    }
    cholmod_dense* B = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &common_);
    std::memcpy(B->x, b.data(), n * sizeof(double));
    cholmod_dense* X = cholmod_l_solve(CHOLMOD_A, L, B, &common_);
    std::memcpy(x.data(), X->x, n * sizeof(double));
    cholmod_l_free_dense(&X, &common_);
    cholmod_l_free_dense(&B, &common_);
    cholmod_l_free_factor(&L, &common_);
    cholmod_l_free_sparse(&M, &common_);
    SolveReport report;
    report.iterations = 1;
    report.relative_residual = relative_residual(A, b, x);
    return report;
  }

 private:
  cholmod_common common_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace washout
