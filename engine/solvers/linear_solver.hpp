#pragma once
// The pressure solvers behind one small interface (METHOD.md step 2: "solve it with a sparse
// solver"). A solver takes the symmetric positive definite PPE matrix and returns x with A x = b.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/solvers/sparse_matrix.hpp"

namespace washout {

struct SolveReport {
  int iterations = 0;              // 1 for a direct solve
  double relative_residual = 0.0;  // |b - A x| / |b|
  bool converged = true;
};

class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Whether solves are exact (a factorisation) rather than iterated to a tolerance.
  virtual bool direct() const { return false; }
  // x holds the initial guess on entry (used by iterative solvers) and the solution on exit.
  virtual SolveReport solve(const CsrMatrix& A, const std::vector<double>& b,
                            std::vector<double>& x) = 0;
  // Another right-hand side for the matrix of the last solve(), unchanged since: a direct solver
  // reuses its factorisation.
  virtual SolveReport solve_again(const CsrMatrix& A, const std::vector<double>& b,
                                  std::vector<double>& x) {
    return solve(A, b, x);
  }
  // solve_again to a relative residual of its own (iterative solvers; a direct solve is exact):
  // for right-hand sides whose solution enters scaled down (the body coupling's responses).
  virtual SolveReport solve_again_to(const CsrMatrix& A, const std::vector<double>& b,
                                     std::vector<double>& x, double /*tolerance*/) {
    return solve_again(A, b, x);
  }
  // solve_again_to for several right-hand sides, each to its own tolerance (the body coupling's
  // responses). An iterative solver runs their iterations side by side, the products of all in
  // one read of the matrix; the others solve one after the other.
  virtual std::vector<SolveReport> solve_many_again_to(
      const CsrMatrix& A, const std::vector<const std::vector<double>*>& b,
      const std::vector<std::vector<double>*>& x, const std::vector<double>& tolerance) {
    std::vector<SolveReport> reports;
    for (std::size_t k = 0; k < b.size(); ++k)
      reports.push_back(solve_again_to(A, *b[k], *x[k], tolerance[k]));
    return reports;
  }
};

// BoomerAMG's settings (hypre's codes; docs/performance.md says how they were chosen).
struct AmgOptions {
  // Solves one set-up serves while the matrix keeps its size (1: a set-up for every matrix);
  // a new set-up comes sooner when a solve takes more than stale_growth times the iterations
  // of the first solve after the set-up (plus two). 40 since the twenty-seventh session (20
  // before): the 3D same-case dam break at a/40 with pcg_amg took 8.8 iterations a step with
  // either, 23 set-ups instead of 35; the paper-resolution set-up takes 4.4 s on one thread
  // (docs/performance.md).
  int reuse_solves = 40;
  double stale_growth = 1.5;
  double strong_threshold = 0.5;  // a connection is strong above this share of the largest
  int coarsening = 10;            // HMIS
  int interpolation = 6;          // extended+i
  int max_interpolation_entries = 4;
  int aggressive_levels = 1;  // levels coarsened aggressively (fewer, cheaper levels)
  // Smoothers going down and coming up the V-cycle: forward then backward l1-Gauss-Seidel (13,
  // 14) make the cycle symmetric, as CG needs, with one sweep each way.
  int relax_down = 13, relax_up = 14;
  // The V-cycle on all threads (threaded_vcycle.hpp: the same cycle with the Gauss-Seidel sweep
  // in row blocks of cycle_block_rows) instead of hypre's own, which runs on one thread in
  // Debian's build. With one block it is hypre's cycle. cycle_block_rows = 0: its default, and
  // hypre's cycle for a matrix too small for two such blocks.
  bool threaded_cycle = true;
  std::size_t cycle_block_rows = 0;
  // The threaded V-cycle reads its matrices' values in single precision (threaded_vcycle.hpp):
  // a third less memory traffic in a solve bound by it; CG around it stays in double.
  bool single_precision_cycle = true;
  // hypre's matrix borrows the solve's columns and values when every row holds its diagonal
  // first (the PPE assembly's matrices), instead of a copy of them; false: always the copy.
  bool borrow_matrix = true;
};

std::unique_ptr<LinearSolver> make_cholmod_solver();
std::unique_ptr<LinearSolver> make_pcg_solver(double tolerance, int max_iterations);
std::unique_ptr<LinearSolver> make_aggregation_pcg_solver(double tolerance, int max_iterations);
std::unique_ptr<LinearSolver> make_amg_pcg_solver(double tolerance, int max_iterations,
                                                  const AmgOptions& options = {});

// The solver a run uses, by the `solver` parameter: "cholmod", "pcg", "pcg_amg", or "auto",
// resolved by the dimension, the number of unknowns and whether dynamic bodies are solved with
// the pressure (docs/parameters.md).
std::string resolve_solver(const std::string& requested, int dim, std::size_t unknowns,
                           bool body_coupled);
// The BoomerAMG settings make_solver gives "pcg_amg": AmgOptions{} unless a benchmark changed
// them (bench_case --amg-reuse).
AmgOptions& default_amg_options();
// A solver by resolved name, counted in solver_counters() (solver_counters.hpp).
std::unique_ptr<LinearSolver> make_solver(const std::string& name, double tolerance,
                                          int max_iterations);

double relative_residual(const CsrMatrix& A, const std::vector<double>& b,
                         const std::vector<double>& x);

}  // namespace washout
