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
  // x holds the initial guess on entry (used by iterative solvers) and the solution on exit.
  virtual SolveReport solve(const CsrMatrix& A, const std::vector<double>& b,
                            std::vector<double>& x) = 0;
  // Another right-hand side for the matrix of the last solve(), unchanged since: a direct solver
  // reuses its factorisation.
  virtual SolveReport solve_again(const CsrMatrix& A, const std::vector<double>& b,
                                  std::vector<double>& x) {
    return solve(A, b, x);
  }
};

std::unique_ptr<LinearSolver> make_cholmod_solver();
std::unique_ptr<LinearSolver> make_pcg_solver(double tolerance, int max_iterations);

double relative_residual(const CsrMatrix& A, const std::vector<double>& b,
                         const std::vector<double>& x);

}  // namespace washout
