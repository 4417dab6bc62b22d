#pragma once
// What the pressure solves of this process cost, summed: for the benchmarks (bench/), which
// read them around a run, and for the matrix dumps they take. Updated by the thread that calls
// the solver (solvers are called outside parallel regions), never read by the physics.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "engine/solvers/sparse_matrix.hpp"

namespace washout {

struct SolverCounters {
  std::string solver;                 // the name of the solver that solved last
  long solves = 0;                    // solve() and solve_again() calls
  long iterations = 0;                // Krylov iterations (1 per direct solve)
  double rows = 0.0, nonzeros = 0.0;  // summed over solves: the mean is / solves
  double solve_seconds = 0.0;         // in solve(), set-up included
  long setups = 0;                    // preconditioner set-ups or factorisations
  long matrix_copies = 0;             // matrices copied into hypre's form (not borrowed)
  double setup_seconds = 0.0;
  // The calling thread's processor time in set-ups (hypre's and CHOLMOD's set-ups run on it):
  // unlike the wall time, not inflated when other work shares the cores.
  double setup_cpu_seconds = 0.0;
  double preconditioner_seconds = 0.0;  // applying the preconditioner in the Krylov loop
  // Matrix-vector products A x of the Krylov loops: their count, time and the bytes they must
  // move at least (csr_product_bytes).
  long products = 0;
  double product_seconds = 0.0, product_bytes = 0.0;
  // Largest operator complexity of an AMG hierarchy built (non-zeros of all levels over those
  // of the matrix; 0 when none was built), and the most memory a preconditioner or factor held
  // (the AMG levels' matrices and interpolations, CHOLMOD's factor, Jacobi's diagonal).
  double operator_complexity = 0.0;
  double setup_bytes = 0.0;
};

SolverCounters& solver_counters();

// The calling thread's processor time so far (CLOCK_THREAD_CPUTIME_ID), in seconds.
double thread_cpu_seconds();

// The least memory traffic of y = A x for A in compressed rows: values and column indices once,
// the row starts once, x once (it fits no cache at the sizes that matter) and y written once.
inline double csr_product_bytes(const CsrMatrix& A) {
  const double n = double(A.rows), nnz = double(A.nonzeros());
  return nnz * (sizeof(double) + sizeof(std::int32_t)) + (n + 1) * sizeof(std::int64_t) +
         2.0 * n * sizeof(double);
}

// Sees every pressure system before it is solved (A, b and the initial guess x): set by a
// benchmark that saves the matrices of a real run (bench/ppe_dump.cpp); empty by default.
using SystemObserver = std::function<void(const CsrMatrix& A, const std::vector<double>& b,
                                          const std::vector<double>& x)>;
void set_system_observer(SystemObserver observer);
const SystemObserver& system_observer();

}  // namespace washout
