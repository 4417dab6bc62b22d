#pragma once
// The preconditioners of the conjugate gradient solver (pcg_solver.cpp): M ~ A, symmetric
// positive definite, applied as z = M^-1 r once per iteration. Jacobi (the diagonal) is built
// here; BoomerAMG (hypre_amg.cpp) is one algebraic multigrid V-cycle.
#include <memory>
#include <vector>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/sparse_matrix.hpp"

namespace washout {

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // Called before each solve with its matrix. same_matrix: A is the matrix of the last call,
  // unchanged (LinearSolver::solve_again), so whatever was built for it still holds.
  virtual void prepare(const CsrMatrix& A, bool same_matrix) = 0;
  virtual void apply(const std::vector<double>& r, std::vector<double>& z) = 0;  // z = M^-1 r
  // After the first solve with a new matrix: the iterations it took (a preconditioner that has
  // gone stale can tell). Not called for solve_again: other right-hand sides, other tolerances.
  virtual void solved(int /*iterations*/) {}
  // A diagonal preconditioner's M^-1 (after prepare), which the CG loop then applies within its
  // own pass over the vectors; null for any other.
  virtual const std::vector<double>* inverse_diagonal() const { return nullptr; }
};

std::unique_ptr<Preconditioner> make_jacobi_preconditioner();
// Jacobi plus a coarse correction on aggregates of neighbouring rows
// (aggregation_preconditioner.cpp).
std::unique_ptr<Preconditioner> make_aggregation_preconditioner();
// One BoomerAMG V-cycle (hypre), options in linear_solver.hpp.
std::unique_ptr<Preconditioner> make_boomeramg_preconditioner(const AmgOptions& options);

}  // namespace washout
