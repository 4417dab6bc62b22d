// One BoomerAMG V-cycle (hypre, Debian's libhypre-dev) as the preconditioner of the conjugate
// gradient (pcg_solver.cpp): coarse grids chosen from the matrix alone, so the iterations stay
// nearly flat as the resolution grows where Jacobi's grow with 1/d0 (docs/performance.md).
//
// hypre is built on MPI: this process is one rank of its own (MPI initialised on first use,
// finalised at exit) and the matrix is one block. The set-up (coarsening, interpolation,
// Galerkin coarse matrices) is the costly part; a V-cycle takes the fine matrix it is given, so
// a hierarchy built for an earlier matrix of the same size still preconditions a later one
// (hypre's solve replaces level 0 by the new matrix; only the coarse levels are stale). The
// V-cycle itself runs on all threads in threaded_vcycle.cpp on hypre's hierarchy, where the
// matrix is large enough to split (Debian's hypre has no OpenMP).
#include <mpi.h>
// hypre's headers after mpi.h; the internal ones (_hypre_*) give the vectors' and matrices'
// arrays, so the data is copied straight in rather than through the IJ interface.
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_ls.h>
#include <_hypre_parcsr_mv.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <string>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/preconditioner.hpp"
#include "engine/solvers/solver_counters.hpp"
#include "engine/solvers/threaded_vcycle.hpp"

namespace washout {
namespace {

void finish_hypre() {
  HYPRE_Finalize();
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

// MPI and hypre once per process. A process not started by mpirun is a singleton: it talks only
// to itself, so it need not start a daemon or probe network transports (0.9 s -> 0.5 s); a
// setting the user made in the environment wins. Nor does it need Open MPI's session directory:
// every isolated singleton of a user shares /tmp/ompi.<host>.<uid>/jf.0, and one run finishing
// removes it while another run starting creates it, so runs side by side (a parameter sweep,
// ctest -j) failed in MPI_Init one time in about a hundred.
void start_hypre() {
  static std::once_flag once;
  std::call_once(once, [] {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr) {
        setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
        setenv("OMPI_MCA_btl", "self", 0);
        setenv("OMPI_MCA_pml", "ob1", 0);
        setenv("OMPI_MCA_orte_create_session_dirs", "0", 0);
      }
      int provided = 0;
      if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw SolverError("hypre: MPI could not be initialised");
    }
    HYPRE_Init();
    if (!initialized) std::atexit(finish_hypre);
  });
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void check(HYPRE_Int error, const char* what) {
  if (error == 0) return;
  char message[256] = {0};
  HYPRE_DescribeError(error, message);
  HYPRE_ClearAllErrors();
  throw SolverError(std::string("hypre ") + what + ": " + message);
}

// A one-rank ParCSR copy of A. hypre wants each row's diagonal entry first.
hypre_ParCSRMatrix* to_parcsr(const CsrMatrix& A) {
  const std::size_t n = A.rows, nnz = A.nonzeros();
  if (n > std::size_t(INT_MAX) || nnz > std::size_t(INT_MAX))
    throw SolverError("hypre: the pressure matrix has more than 2^31 rows or non-zeros (" +
                      std::to_string(nnz) + " non-zeros), beyond this build's 32-bit indices");
  HYPRE_BigInt starts[2] = {0, HYPRE_BigInt(n)};
  hypre_ParCSRMatrix* M = hypre_ParCSRMatrixCreate(MPI_COMM_WORLD, HYPRE_BigInt(n), HYPRE_BigInt(n),
                                                   starts, starts, 0, HYPRE_Int(nnz), 0);
  hypre_ParCSRMatrixInitialize(M);
  hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(M);
  HYPRE_Int* row = hypre_CSRMatrixI(diag);
  HYPRE_Int* col = hypre_CSRMatrixJ(diag);
  HYPRE_Real* val = hypre_CSRMatrixData(diag);
  for (std::size_t i = 0; i <= n; ++i) row[i] = HYPRE_Int(A.row_start[i]);
  std::size_t missing_diagonal = n;
#pragma omp parallel for schedule(static) reduction(min : missing_diagonal) if (n > 20000)
  for (std::size_t i = 0; i < n; ++i) {
    HYPRE_Int out = row[i] + 1;  // row[i] is kept for the diagonal
    bool has_diagonal = false;
    for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k) {
      if (std::size_t(A.column[k]) == i && !has_diagonal) {
        col[row[i]] = HYPRE_Int(i);
        val[row[i]] = A.value[k];
        has_diagonal = true;
      } else if (out < row[i + 1]) {
        col[out] = A.column[k];
        val[out++] = A.value[k];
      }
    }
    if (!has_diagonal) missing_diagonal = std::min(missing_diagonal, i);
  }
  if (missing_diagonal < n) {
    hypre_ParCSRMatrixDestroy(M);
    throw SolverError("hypre: row " + std::to_string(missing_diagonal) +
                      " of the pressure matrix has no diagonal entry");
  }
  hypre_ParCSRMatrixSetNumNonzeros(M);
  return M;
}

// A one-rank ParCSR matrix that borrows A's columns and values, when every row already holds
// its diagonal first (as the PPE assembly writes it, engine/fluid/ppe_matrix.cpp): hypre owns
// only its 32-bit row starts (its data-owner flag is off, so destroying it leaves A's arrays),
// where to_parcsr copied the whole matrix (600 MB and about 0.03 s a step at the paper's
// resolution). nullptr for a matrix in another order, which takes the copy. The borrowed arrays
// must not move while hypre reads them: each prepare() makes a new one for its matrix, and
// hypre reads the set-up's only during the set-up (its V-cycle takes each solve's matrix as
// level 0). The same bits as the copy, and BoomerAMG leaves the borrowed arrays as they were
// (tests/unit/test_pressure_solvers.cpp, AmgBorrowsTheMatrixForTheSameBits).
hypre_ParCSRMatrix* borrow_parcsr(const CsrMatrix& A) {
  const std::size_t n = A.rows, nnz = A.nonzeros();
  if (n > std::size_t(INT_MAX) || nnz > std::size_t(INT_MAX)) return nullptr;
  static_assert(sizeof(HYPRE_Int) == sizeof(std::int32_t) && sizeof(HYPRE_Real) == sizeof(double));
  std::size_t diagonal_first = 1;
#pragma omp parallel for schedule(static) reduction(min : diagonal_first) if (n > 20000)
  for (std::size_t i = 0; i < n; ++i)
    if (A.row_start[i] == A.row_start[i + 1] || std::size_t(A.column[A.row_start[i]]) != i)
      diagonal_first = 0;
  if (!diagonal_first) return nullptr;
  HYPRE_BigInt starts[2] = {0, HYPRE_BigInt(n)};
  hypre_ParCSRMatrix* M = hypre_ParCSRMatrixCreate(MPI_COMM_WORLD, HYPRE_BigInt(n), HYPRE_BigInt(n),
                                                   starts, starts, 0, HYPRE_Int(nnz), 0);
  hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(M);
  // Set before Initialize, which then allocates only what is missing (the row starts, and the
  // empty off-diagonal block's).
  hypre_CSRMatrixJ(diag) = const_cast<HYPRE_Int*>(A.column.data());
  hypre_CSRMatrixData(diag) = const_cast<HYPRE_Real*>(A.value.data());
  hypre_CSRMatrixSetDataOwner(diag, 0);
  hypre_ParCSRMatrixInitialize(M);
  HYPRE_Int* row = hypre_CSRMatrixI(diag);
  for (std::size_t i = 0; i <= n; ++i) row[i] = HYPRE_Int(A.row_start[i]);
  hypre_ParCSRMatrixSetNumNonzeros(M);
  return M;
}

hypre_ParVector* make_vector(std::size_t n) {
  HYPRE_BigInt starts[2] = {0, HYPRE_BigInt(n)};
  hypre_ParVector* v = hypre_ParVectorCreate(MPI_COMM_WORLD, HYPRE_BigInt(n), starts);
  hypre_ParVectorInitialize(v);
  return v;
}

HYPRE_Real* data(hypre_ParVector* v) { return hypre_VectorData(hypre_ParVectorLocalVector(v)); }

// A one-rank ParCSR matrix's arrays (its diag block holds everything).
CsrView view(hypre_ParCSRMatrix* M) {
  hypre_CSRMatrix* d = hypre_ParCSRMatrixDiag(M);
  CsrView v;
  v.rows = static_cast<std::size_t>(hypre_CSRMatrixNumRows(d));
  v.columns = static_cast<std::size_t>(hypre_CSRMatrixNumCols(d));
  v.row_start = hypre_CSRMatrixI(d);
  v.column = hypre_CSRMatrixJ(d);
  v.value = hypre_CSRMatrixData(d);
  return v;
}

class BoomerAmg final : public Preconditioner {
 public:
  explicit BoomerAmg(const AmgOptions& options) : options_(options) {
    if (options_.reuse_solves < 1) throw SolverError("hypre: reuse_solves must be at least 1");
    start_hypre();
  }
  ~BoomerAmg() override { release(); }
  BoomerAmg(const BoomerAmg&) = delete;
  BoomerAmg& operator=(const BoomerAmg&) = delete;

  void prepare(const CsrMatrix& A, bool same_matrix) override {
    if (same_matrix && matrix_ && rows_ == A.rows) return;
    auto& counters = solver_counters();
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    if (matrix_) hypre_ParCSRMatrixDestroy(matrix_);
    matrix_ = options_.borrow_matrix ? borrow_parcsr(A) : nullptr;
    if (!matrix_) {
      matrix_ = to_parcsr(A);
      ++counters.matrix_copies;
    }
    const bool reuse = amg_ && rows_ == A.rows && uses_ < options_.reuse_solves && !stale_;
    if (!reuse) {
      // The threaded cycle's views of the old hierarchy go with it, and its rounded copies are
      // freed before hypre's set-up allocates the new one.
      if (amg_) HYPRE_BoomerAMGDestroy(amg_);
      vcycle_.release();
      if (setup_matrix_) hypre_ParCSRMatrixDestroy(setup_matrix_);
      amg_ = nullptr;
      setup_matrix_ = nullptr;
      if (!f_ || rows_ != A.rows) {
        destroy_vectors();
        f_ = make_vector(A.rows);
        u_ = make_vector(A.rows);
        rows_ = A.rows;
      }
      create();
      check(HYPRE_BoomerAMGSetup(amg_, reinterpret_cast<HYPRE_ParCSRMatrix>(matrix_),
                                 reinterpret_cast<HYPRE_ParVector>(f_),
                                 reinterpret_cast<HYPRE_ParVector>(u_)),
            "BoomerAMG set-up");
      // The hierarchy keeps the set-up matrix as its level 0 until the next V-cycle of hypre's:
      // it stays alive with it (a later prepare() builds the new fine matrix beside it), unless
      // the threaded cycle takes over (below).
      setup_matrix_ = matrix_;
      matrix_ = nullptr;
      uses_ = 0;
      fresh_iterations_ = -1;
      stale_ = false;
      ++counters.setups;
      record_hierarchy(A);
      build_threaded_cycle();
      if (threaded_) {
        // The threaded cycle reads the hierarchy's coarse levels only, and each solve gives it
        // the fine matrix: the set-up's copy need not outlive this step's solves. One hypre copy
        // of the fine matrix instead of two (600 MB at the paper's resolution); hypre's
        // hierarchy never frees or reads its level 0 again (BoomerAMGDestroy starts at level 1).
        hypre_ParAMGDataAArray(reinterpret_cast<hypre_ParAMGData*>(amg_))[0] = nullptr;
        matrix_ = setup_matrix_;
        setup_matrix_ = nullptr;
      }
    }
    // The cycle's fine level is this solve's matrix (in single precision a rounded copy of it).
    if (threaded_) vcycle_.set_fine(view(matrix_ ? matrix_ : setup_matrix_));
    ++uses_;
    counters.setup_seconds += seconds_since(start);
    counters.setup_cpu_seconds += thread_cpu_seconds() - cpu_start;
  }

  void solved(int iterations) override {
    if (fresh_iterations_ < 0)
      fresh_iterations_ = iterations;
    else if (iterations > options_.stale_growth * fresh_iterations_ + 2)
      stale_ = true;  // the coarse levels no longer fit the matrix: a new set-up next time
  }

  void apply(const std::vector<double>& r, std::vector<double>& z) override {
    const std::size_t n = r.size();
    z.resize(n);
    if (threaded_) {
      vcycle_.apply(r.data(), z.data());
      return;
    }
    HYPRE_Real* f = data(f_);
    HYPRE_Real* u = data(u_);
    for (std::size_t i = 0; i < n; ++i) {
      f[i] = r[i];
      u[i] = 0.0;
    }
    hypre_ParCSRMatrix* fine = matrix_ ? matrix_ : setup_matrix_;
    check(HYPRE_BoomerAMGSolve(amg_, reinterpret_cast<HYPRE_ParCSRMatrix>(fine),
                               reinterpret_cast<HYPRE_ParVector>(f_),
                               reinterpret_cast<HYPRE_ParVector>(u_)),
          "BoomerAMG V-cycle");
    for (std::size_t i = 0; i < n; ++i) z[i] = u[i];
  }

 private:
  void create() {
    HYPRE_BoomerAMGCreate(&amg_);
    HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
    HYPRE_BoomerAMGSetMaxIter(amg_, 1);  // one V-cycle per application
    HYPRE_BoomerAMGSetTol(amg_, 0.0);    // and no residual computed for a stopping test
    HYPRE_BoomerAMGSetCoarsenType(amg_, options_.coarsening);
    HYPRE_BoomerAMGSetInterpType(amg_, options_.interpolation);
    HYPRE_BoomerAMGSetPMaxElmts(amg_, options_.max_interpolation_entries);
    HYPRE_BoomerAMGSetAggNumLevels(amg_, options_.aggressive_levels);
    HYPRE_BoomerAMGSetStrongThreshold(amg_, options_.strong_threshold);
    // A backward sweep up the cycle mirrors the forward one down it, both in lexicographic
    // order: the V-cycle is a symmetric operator, as CG needs. Gaussian elimination at the
    // coarsest level.
    HYPRE_BoomerAMGSetCycleRelaxType(amg_, options_.relax_down, 1);
    HYPRE_BoomerAMGSetCycleRelaxType(amg_, options_.relax_up, 2);
    HYPRE_BoomerAMGSetCycleRelaxType(amg_, 9, 3);
    HYPRE_BoomerAMGSetRelaxOrder(amg_, 0);
    HYPRE_BoomerAMGSetNumSweeps(amg_, 1);
  }

  // The threaded V-cycle on the hierarchy just built (its coarse levels and interpolations stay
  // hypre's; level 0 is each solve's own matrix, as in hypre's cycle).
  void build_threaded_cycle() {
    auto* data = reinterpret_cast<hypre_ParAMGData*>(amg_);
    const int levels = hypre_ParAMGDataNumLevels(data);
    // A fine level too small for two default blocks would sweep on one thread anyway: hypre's
    // cycle there, unless a block size was asked for.
    const std::size_t rows = std::size_t(hypre_ParCSRMatrixGlobalNumRows(setup_matrix_));
    // It implements the default smoother only (l1-Gauss-Seidel, 13 down and 14 up, which on one
    // rank is Gauss-Seidel); other smoothers keep hypre's cycle.
    const bool gauss_seidel = options_.relax_down == 13 && options_.relax_up == 14;
    threaded_ = options_.threaded_cycle && gauss_seidel && levels >= 2 &&
                (options_.cycle_block_rows > 0 || rows >= 2 * ThreadedVCycle::kDefaultBlockRows);
    if (!threaded_) return;
    std::vector<CsrView> A(levels), P(levels - 1);
    for (int l = 1; l < levels; ++l) A[l] = view(hypre_ParAMGDataAArray(data)[l]);
    for (int l = 0; l + 1 < levels; ++l) P[l] = view(hypre_ParAMGDataPArray(data)[l]);
    vcycle_.build(A, P, options_.cycle_block_rows,
                  options_.single_precision_cycle ? CyclePrecision::single_precision
                                                  : CyclePrecision::double_precision);
  }

  void record_hierarchy(const CsrMatrix& A) {
    auto* data = reinterpret_cast<hypre_ParAMGData*>(amg_);
    const int levels = hypre_ParAMGDataNumLevels(data);
    double nonzeros = 0.0, bytes = 0.0;
    for (int l = 0; l < levels; ++l) {
      hypre_ParCSRMatrix* M = hypre_ParAMGDataAArray(data)[l];
      const double nnz = double(hypre_CSRMatrixNumNonzeros(hypre_ParCSRMatrixDiag(M)));
      const double rows = double(hypre_ParCSRMatrixGlobalNumRows(M));
      nonzeros += nnz;
      bytes += nnz * (sizeof(HYPRE_Real) + sizeof(HYPRE_Int)) + rows * sizeof(HYPRE_Int);
      if (l + 1 < levels) {
        hypre_ParCSRMatrix* P = hypre_ParAMGDataPArray(data)[l];
        const double p_nnz = double(hypre_CSRMatrixNumNonzeros(hypre_ParCSRMatrixDiag(P)));
        bytes += p_nnz * (sizeof(HYPRE_Real) + sizeof(HYPRE_Int)) + rows * sizeof(HYPRE_Int);
      }
    }
    auto& counters = solver_counters();
    const double complexity = A.nonzeros() > 0 ? nonzeros / double(A.nonzeros()) : 0.0;
    if (complexity > counters.operator_complexity) counters.operator_complexity = complexity;
    if (bytes > counters.setup_bytes) counters.setup_bytes = bytes;
  }

  void destroy_vectors() {
    if (f_) hypre_ParVectorDestroy(f_);
    if (u_) hypre_ParVectorDestroy(u_);
    f_ = u_ = nullptr;
  }
  void release() {
    if (amg_) HYPRE_BoomerAMGDestroy(amg_);
    if (matrix_) hypre_ParCSRMatrixDestroy(matrix_);
    if (setup_matrix_) hypre_ParCSRMatrixDestroy(setup_matrix_);
    destroy_vectors();
    amg_ = nullptr;
    matrix_ = setup_matrix_ = nullptr;
  }

  AmgOptions options_;
  HYPRE_Solver amg_ = nullptr;
  hypre_ParCSRMatrix* setup_matrix_ = nullptr;  // the matrix the hierarchy was built from
  hypre_ParCSRMatrix* matrix_ = nullptr;        // a later matrix it preconditions (reuse)
  hypre_ParVector *f_ = nullptr, *u_ = nullptr;
  ThreadedVCycle vcycle_;
  bool threaded_ = false;  // the V-cycle is vcycle_'s, not hypre's
  std::size_t rows_ = 0;
  int uses_ = 0;               // solves since the last set-up
  int fresh_iterations_ = -1;  // iterations of the first solve after it
  bool stale_ = false;         // a later solve took too many more
};

}  // namespace

std::unique_ptr<Preconditioner> make_boomeramg_preconditioner(const AmgOptions& options) {
  return std::make_unique<BoomerAmg>(options);
}

}  // namespace washout
