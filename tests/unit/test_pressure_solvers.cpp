// The pressure solvers behind make_solver: the multigrid-preconditioned CG (BoomerAMG) and the
// aggregates' two-level CG against Jacobi CG on Poisson matrices of growing size, the reuse of a
// set-up across solves, the counters the benchmark reads, and the errors a wrong matrix or name
// gives.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/solver_counters.hpp"
#include "engine/solvers/symmetric_product.hpp"

namespace washout {
namespace {

// -lap u = f on an n^3 grid, Dirichlet outside, seven-point stencil scaled by `scale` (the PPE
// is a scaled Laplacian too); the diagonal is stored in the middle of each row, as the PPE
// assembly does not put it first.
CsrMatrix laplacian_3d(int n, double scale = 1.0) {
  CsrMatrix A;
  A.rows = std::size_t(n) * n * n;
  A.row_start.push_back(0);
  auto index = [n](int i, int j, int k) { return std::int32_t((k * n + j) * n + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        auto add = [&](int ii, int jj, int kk, double v) {
          if (ii < 0 || jj < 0 || kk < 0 || ii >= n || jj >= n || kk >= n) return;
          A.column.push_back(index(ii, jj, kk));
          A.value.push_back(v * scale);
        };
        add(i, j, k - 1, -1);
        add(i, j - 1, k, -1);
        add(i - 1, j, k, -1);
        add(i, j, k, 6);
        add(i + 1, j, k, -1);
        add(i, j + 1, k, -1);
        add(i, j, k + 1, -1);
        A.row_start.push_back(std::int64_t(A.value.size()));
      }
  return A;
}

std::vector<double> smooth_rhs(std::size_t rows) {
  std::vector<double> b(rows);
  for (std::size_t i = 0; i < rows; ++i) b[i] = 1.0 + std::sin(0.01 * double(i));
  return b;
}

int iterations(LinearSolver& solver, const CsrMatrix& A) {
  const auto b = smooth_rhs(A.rows);
  std::vector<double> x(A.rows, 0.0);
  const auto report = solver.solve(A, b, x);
  EXPECT_TRUE(report.converged);
  EXPECT_LT(relative_residual(A, b, x), 1e-8);
  return report.iterations;
}

// solve_many_again_to: seven right-hand sides of one matrix iterated side by side (the body
// coupling's responses), each to its own tolerance, against the same solves one at a time: the
// same iterations (the same CG, only the products' sums in another order) and each residual
// within its tolerance. And multiply_many against one product at a time.
TEST(PressureSolvers, SeveralRightHandSidesSideBySide) {
  const CsrMatrix A = laplacian_3d(20);
  for (const std::string name : {"pcg", "pcg_agg", "pcg_amg"}) {
    auto solver = make_solver(name, 1e-8, 1000);
    std::vector<double> x0(A.rows, 0.0);
    solver->solve(A, smooth_rhs(A.rows), x0);  // the matrix's first solve, as in a step
    std::vector<std::vector<double>> b(7), together(7), alone(7);
    std::vector<double> tolerance;
    for (std::size_t k = 0; k < b.size(); ++k) {
      b[k].resize(A.rows);
      for (std::size_t i = 0; i < A.rows; ++i) b[k][i] = std::cos(0.01 * double(i * (k + 2)));
      together[k].assign(A.rows, 0.0);
      alone[k].assign(A.rows, 0.0);
      tolerance.push_back(k == 3 ? 1e30 : std::pow(10.0, -2.0 - double(k)));
    }
    b[5].assign(A.rows, 0.0);  // a zero right-hand side: x = 0, no iterations
    together[5].assign(A.rows, 1.0);
    std::vector<const std::vector<double>*> right;
    std::vector<std::vector<double>*> unknown;
    for (std::size_t k = 0; k < b.size(); ++k)
      right.push_back(&b[k]), unknown.push_back(&together[k]);
    const auto reports = solver->solve_many_again_to(A, right, unknown, tolerance);
    ASSERT_EQ(reports.size(), b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
      const SolveReport one = solver->solve_again_to(A, b[k], alone[k], tolerance[k]);
      std::printf("%s, tolerance %.0e: %d iterations side by side, %d alone\n", name.c_str(),
                  tolerance[k], reports[k].iterations, one.iterations);
      EXPECT_TRUE(reports[k].converged);
      EXPECT_NEAR(reports[k].iterations, one.iterations, 1) << name << " system " << k;
      if (k == 5) {
        EXPECT_EQ(reports[k].iterations, 0);
        for (double v : together[k]) ASSERT_EQ(v, 0.0);
        continue;
      }
      if (k == 3) {
        EXPECT_EQ(reports[k].iterations, 0);
      }
      EXPECT_LE(relative_residual(A, b[k], together[k]), tolerance[k] * 1.000001)
          << name << " system " << k;
    }
    // Nothing to iterate: no product made or counted.
    const double bytes = solver_counters().product_bytes;
    std::vector<double> zero(A.rows, 0.0), guess(A.rows, 1.0);
    const auto none = solver->solve_many_again_to(A, {&zero}, {&guess}, {1e-6});
    EXPECT_EQ(none[0].iterations, 0);
    EXPECT_EQ(solver_counters().product_bytes, bytes);
    EXPECT_EQ(guess[0], 0.0);
  }
  std::vector<const std::vector<double>*> x;
  std::vector<std::vector<double>> y(8), v(8);
  std::vector<std::vector<double>*> out;
  for (std::size_t k = 0; k < v.size(); ++k) {
    v[k] = smooth_rhs(A.rows);
    for (std::size_t i = 0; i < A.rows; ++i) v[k][i] *= double(k + 1) + 0.001 * double(i % 7);
    x.push_back(&v[k]);
    out.push_back(&y[k]);
  }
  multiply_many(A, x, out);
  for (std::size_t k = 0; k < v.size(); ++k) {
    std::vector<double> one;
    A.multiply(v[k], one);
    for (std::size_t i = 0; i < A.rows; ++i)
      ASSERT_NEAR(y[k][i], one[i], 1e-12 * (1.0 + std::abs(one[i]))) << "vector " << k;
  }
}

TEST(PressureSolvers, IterationsStayFlatWhereJacobiGrows) {
  // From 12^3 to 36^3 unknowns (27 times as many): Jacobi's iterations grow about with n. The
  // V-cycle's must not; nor may the aggregates' coarse system's, which takes the long waves
  // whatever the size (it may grow a little: the aggregates' size is fixed, the share of the
  // spectrum the coarse system covers is not).
  const CsrMatrix small = laplacian_3d(12), large = laplacian_3d(36);
  auto jacobi = make_solver("pcg", 1e-8, 10000);
  const int jacobi_small = iterations(*jacobi, small);
  const int jacobi_large = iterations(*jacobi, large);
  EXPECT_GT(jacobi_large, 2 * jacobi_small);
  struct Bound {
    const char* solver;
    int slack;              // iterations on the large matrix <= 1.5 x small + slack
    int fewer_than_jacobi;  // and < Jacobi's on it / this
  };
  for (const Bound& bound : {Bound{"pcg_amg", 1, 3}, Bound{"pcg_agg", 2, 2}}) {
    auto solver = make_solver(bound.solver, 1e-8, 10000);
    const int its_small = iterations(*solver, small);
    const int its_large = iterations(*solver, large);
    std::printf("Jacobi CG %d -> %d iterations, %s %d -> %d\n", jacobi_small, jacobi_large,
                bound.solver, its_small, its_large);
    EXPECT_LE(its_large, 1.5 * its_small + bound.slack) << bound.solver;
    EXPECT_LT(its_large, jacobi_large / bound.fewer_than_jacobi) << bound.solver;
  }
}

// The solution of pcg_agg on `threads` threads (aggregates made in fixed blocks of rows, the
// restriction summed per aggregate: nothing may depend on the thread count).
std::vector<double> aggregation_solution(int threads, const CsrMatrix& A) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  auto solver = make_solver("pcg_agg", 1e-10, 10000);
  std::vector<double> x(A.rows, 0.0);
  EXPECT_TRUE(solver->solve(A, smooth_rhs(A.rows), x).converged);
  omp_set_num_threads(before);
  return x;
}

TEST(PressureSolvers, AggregationGivesTheSameBitsOnAnyThreadCount) {
  const CsrMatrix A = laplacian_3d(24, 3.0);  // 13,824 rows: seven blocks of aggregates
  const std::vector<double> one = aggregation_solution(1, A);
  for (int threads : {2, 3})
    EXPECT_EQ(aggregation_solution(threads, A), one) << threads << " threads";
}

TEST(PressureSolvers, AggregationSolvesGivenRowsExactly) {
  // Rows holding only their diagonal (a given pressure with pcg_agg's stable rows: an isolated
  // particle, a squeeze film) belong to no aggregate: Jacobi solves them, and the rest as before.
  CsrMatrix A = laplacian_3d(10);
  std::vector<std::uint8_t> given(A.rows, 0);
  for (std::size_t i = 0; i < A.rows; i += 7) given[i] = 1;
  CsrMatrix B;
  B.rows = A.rows;
  B.row_start.push_back(0);
  for (std::size_t i = 0; i < A.rows; ++i) {
    for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(A.column[k]);
      if (j != i && (given[i] || given[j])) continue;  // decoupled, as a given row's neighbours
      B.column.push_back(A.column[k]);
      B.value.push_back(given[i] ? 1.0 : A.value[k]);
    }
    B.row_start.push_back(std::int64_t(B.value.size()));
  }
  auto b = smooth_rhs(B.rows);
  for (std::size_t i = 0; i < B.rows; ++i)
    if (given[i]) b[i] = 0.0;
  auto solver = make_solver("pcg_agg", 1e-10, 1000);
  std::vector<double> x(B.rows, 1.0);
  ASSERT_TRUE(solver->solve(B, b, x).converged);
  EXPECT_LT(relative_residual(B, b, x), 1e-10);
  // Within the solve's tolerance of zero (CG's common step leaves them as it leaves the rest).
  double b_norm = 0.0;
  for (const double v : b) b_norm += v * v;
  for (std::size_t i = 0; i < B.rows; ++i) {
    if (!given[i]) continue;
    EXPECT_LT(std::abs(x[i]), 1e-10 * std::sqrt(b_norm)) << "row " << i;
  }
}

// Solves laplacian_3d(16) scaled by each of `scales` in turn (the PPE's scale changes with dt),
// each to 1e-8, checking the set-ups counted after each against `setups_after`; then a matrix of
// another size (one set-up more) and another right-hand side for it (none).
void expect_setups(LinearSolver& solver, const std::vector<double>& scales,
                   const std::vector<long>& setups_after) {
  const auto& counters = solver_counters();
  for (std::size_t k = 0; k < scales.size(); ++k) {
    const CsrMatrix A = laplacian_3d(16, scales[k]);
    const auto b = smooth_rhs(A.rows);
    std::vector<double> x(A.rows, 0.0);
    EXPECT_TRUE(solver.solve(A, b, x).converged);
    EXPECT_LT(relative_residual(A, b, x), 1e-8) << "scale " << scales[k];
    EXPECT_EQ(counters.setups, setups_after[k]) << "matrix " << k;
  }
  const long before = counters.setups;
  const CsrMatrix other = laplacian_3d(17);
  std::vector<double> x(other.rows, 0.0);
  EXPECT_TRUE(solver.solve(other, smooth_rhs(other.rows), x).converged);
  EXPECT_EQ(counters.setups, before + 1);
  EXPECT_TRUE(solver.solve_again(other, smooth_rhs(other.rows), x).converged);
  EXPECT_EQ(counters.setups, before + 1);
  EXPECT_GT(counters.setup_bytes, 0.0);
}

TEST(PressureSolvers, AggregationSetupServesTenMatricesOfOneSize) {
  // One set-up for the first ten matrices of a size, each solved with the diagonal of its own, a
  // new one for the eleventh.
  solver_counters() = SolverCounters{};
  auto solver = make_solver("pcg_agg", 1e-8, 1000);
  std::vector<double> scales;
  std::vector<long> setups;
  for (int k = 0; k < 11; ++k) {
    scales.push_back(1.0 + 0.1 * k);
    setups.push_back(k < 10 ? 1 : 2);
  }
  expect_setups(*solver, scales, setups);
}

// A pcg_amg solver whose set-up serves `reuse` solves, the solver counters zeroed; with
// cycle_block_rows > 0 its V-cycle is the threaded one in blocks of that many rows.
std::unique_ptr<LinearSolver> amg_solver_counted_afresh(int reuse, double tolerance,
                                                        std::size_t cycle_block_rows = 0) {
  AmgOptions options;
  options.reuse_solves = reuse;
  options.cycle_block_rows = cycle_block_rows;
  solver_counters() = SolverCounters{};
  return make_amg_pcg_solver(tolerance, 1000, options);
}

void expect_setup_serves_later_matrices(std::size_t cycle_block_rows) {
  auto solver = amg_solver_counted_afresh(3, 1e-8, cycle_block_rows);
  expect_setups(*solver, {1.0, 1.3, 0.7}, {1, 1, 1});
  EXPECT_GT(solver_counters().operator_complexity, 1.0);
}

TEST(PressureSolvers, AmgSetupServesLaterMatricesOfTheSameSize) {
  expect_setup_serves_later_matrices(0);  // 4,096 rows: hypre's own cycle
}

// The threaded cycle keeps no copy of the set-up's fine matrix (hypre_amg.cpp): the later
// matrices, the new size's set-up and another right-hand side must all still be solved.
TEST(PressureSolvers, AmgSetupServesLaterMatricesWithTheThreadedCycle) {
  expect_setup_serves_later_matrices(1024);  // four blocks
}

// The PPE assembly writes each row's diagonal first, and hypre's matrix then borrows the
// columns and values instead of copying them (hypre_amg.cpp): the same solution to the bit as
// with the copy, over a set-up and a reused one, with hypre's cycle and the threaded one, and
// the borrowed arrays untouched.
CsrMatrix with_diagonal_first(const CsrMatrix& A) {
  CsrMatrix B = A;
  for (std::size_t i = 0; i < A.rows; ++i) {
    std::int64_t out = B.row_start[i] + 1;
    for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k) {
      if (std::size_t(A.column[k]) == i) {
        B.column[B.row_start[i]] = A.column[k];
        B.value[B.row_start[i]] = A.value[k];
      } else {
        B.column[out] = A.column[k];
        B.value[out++] = A.value[k];
      }
    }
  }
  return B;
}

TEST(PressureSolvers, AmgBorrowsTheMatrixForTheSameBits) {
  const CsrMatrix first = with_diagonal_first(laplacian_3d(24)),
                  later = with_diagonal_first(laplacian_3d(24, 1.3));
  for (const std::size_t block_rows : {std::size_t(0), std::size_t(2048)}) {
    std::vector<std::vector<double>> solutions;
    for (const bool borrow : {true, false}) {
      AmgOptions options;
      options.cycle_block_rows = block_rows;
      options.borrow_matrix = borrow;
      auto solver = make_amg_pcg_solver(1e-10, 1000, options);
      solver_counters() = SolverCounters{};
      const CsrMatrix copy_of_first = first;
      std::vector<double> x(first.rows, 0.0), y(first.rows, 0.0);
      ASSERT_TRUE(solver->solve(first, smooth_rhs(first.rows), x).converged);
      ASSERT_TRUE(solver->solve(later, smooth_rhs(later.rows), y).converged);  // set-up reused
      EXPECT_EQ(first.value, copy_of_first.value);
      EXPECT_EQ(first.column, copy_of_first.column);
      EXPECT_EQ(solver_counters().matrix_copies, borrow ? 0 : 2);
      x.insert(x.end(), y.begin(), y.end());
      solutions.push_back(x);
    }
    EXPECT_EQ(solutions[0], solutions[1]) << "cycle_block_rows " << block_rows;
  }
}

TEST(PressureSolvers, AmgStalenessIsJudgedOnNewMatricesOnly) {
  // The body coupling solves each step's matrix again for its responses, from other guesses and
  // to other tolerances: many more iterations than the step's own solve without the hierarchy
  // having gone stale. Those must not force a new set-up; a later matrix of the same size keeps
  // the hierarchy.
  auto solver = amg_solver_counted_afresh(10, 1e-4);
  const auto& counters = solver_counters();
  const CsrMatrix A = laplacian_3d(16);
  std::vector<double> x(A.rows, 0.0);
  const SolveReport first = solver->solve(A, smooth_rhs(A.rows), x);
  std::vector<double> b(A.rows), response(A.rows, 0.0);
  for (std::size_t i = 0; i < A.rows; ++i) b[i] = std::cos(0.37 * double(i));
  const SolveReport tight = solver->solve_again_to(A, b, response, 1e-13);
  std::printf("step solve %d iterations, response to 1e-13 %d\n", first.iterations,
              tight.iterations);
  ASSERT_TRUE(tight.converged);
  ASSERT_GT(tight.iterations, AmgOptions{}.stale_growth * first.iterations + 2);  // old trigger
  const CsrMatrix later = laplacian_3d(16, 1.2);
  EXPECT_TRUE(solver->solve(later, smooth_rhs(later.rows), x).converged);
  EXPECT_EQ(counters.setups, 1);
}

TEST(PressureSolvers, CountersFollowTheKrylovLoop) {
  auto solver = make_solver("pcg", 1e-8, 1000);
  auto& counters = solver_counters();
  counters = SolverCounters{};
  const CsrMatrix A = laplacian_3d(10);
  std::vector<double> x(A.rows, 0.0);
  const auto report = solver->solve(A, smooth_rhs(A.rows), x);
  EXPECT_EQ(counters.solves, 1);
  EXPECT_EQ(counters.solver, "pcg");
  EXPECT_EQ(counters.iterations, report.iterations);
  EXPECT_EQ(counters.products, report.iterations + 1);  // one for the initial residual
  // The products from the upper triangle (symmetric_product.hpp), counted by their own bytes.
  SymmetricProduct product;
  ASSERT_TRUE(product.build(A));
  EXPECT_DOUBLE_EQ(counters.product_bytes, counters.products * product.product_bytes());
  EXPECT_LT(product.product_bytes(), csr_product_bytes(A));
  EXPECT_DOUBLE_EQ(counters.nonzeros, double(A.nonzeros()));
  // BoomerAMG CG multiplies by the full rows (its set-up needs them; a second copy of half the
  // matrix saved it no time).
  auto amg = make_solver("pcg_amg", 1e-8, 1000);
  counters = SolverCounters{};
  std::vector<double> y(A.rows, 0.0);
  amg->solve(A, smooth_rhs(A.rows), y);
  ASSERT_GT(counters.products, 0);
  EXPECT_DOUBLE_EQ(counters.product_bytes, counters.products * csr_product_bytes(A));
}

TEST(PressureSolvers, ObserverSeesEachSystemBeforeItIsSolved) {
  auto solver = make_solver("pcg", 1e-8, 1000);
  std::size_t seen_rows = 0;
  double seen_guess = -1.0;
  set_system_observer(
      [&](const CsrMatrix& A, const std::vector<double>&, const std::vector<double>& x) {
        seen_rows = A.rows;
        seen_guess = x[0];
      });
  const CsrMatrix A = laplacian_3d(5);
  std::vector<double> x(A.rows, 0.25);
  solver->solve(A, smooth_rhs(A.rows), x);
  set_system_observer(nullptr);
  EXPECT_EQ(seen_rows, A.rows);
  EXPECT_EQ(seen_guess, 0.25);  // the guess, not the solution
}

TEST(PressureSolvers, AutoPicksByDimensionAndSize) {
  EXPECT_EQ(resolve_solver("pcg", 2, 10, false), "pcg");
  EXPECT_EQ(resolve_solver("pcg_amg", 3, 10, true), "pcg_amg");
  EXPECT_EQ(resolve_solver("auto", 2, 1000, false), "cholmod");
  EXPECT_EQ(resolve_solver("auto", 2, 3200, false), "pcg_agg");
  EXPECT_EQ(resolve_solver("auto", 2, 99999, false), "pcg_agg");
  EXPECT_EQ(resolve_solver("auto", 2, 100000, false), "pcg_amg");
  EXPECT_EQ(resolve_solver("auto", 2, 3200, true), "cholmod");
  EXPECT_EQ(resolve_solver("auto", 2, 1000000, true), "pcg_amg");
  EXPECT_EQ(resolve_solver("auto", 3, 500, false), "pcg_agg");
  EXPECT_EQ(resolve_solver("auto", 3, 10000, true), "pcg_agg");
  EXPECT_EQ(resolve_solver("auto", 3, 99999, false), "pcg_agg");
  EXPECT_EQ(resolve_solver("auto", 3, 100000, false), "pcg_amg");
}

TEST(PressureSolvers, ClearErrors) {
  try {
    make_solver("multigrid", 1e-8, 100);
    FAIL() << "an unknown solver name was accepted";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("multigrid"), std::string::npos);
  }
  // An indefinite matrix is refused by the direct solver, not factorised as LDL' in silence.
  {
    CsrMatrix B;
    B.rows = 2;
    B.row_start = {0, 2, 4};
    B.column = {0, 1, 0, 1};
    B.value = {1.0, 2.0, 2.0, 1.0};  // eigenvalues 3 and -1
    auto cholmod = make_solver("cholmod", 1e-8, 100);
    std::vector<double> y(2, 0.0);
    try {
      cholmod->solve(B, {1.0, 1.0}, y);
      FAIL() << "an indefinite matrix was factorised";
    } catch (const SolverError& e) {
      EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
    }
  }
  // A row without its diagonal entry cannot be handed to BoomerAMG.
  CsrMatrix A = laplacian_3d(3);
  for (std::int64_t k = A.row_start[4]; k < A.row_start[5]; ++k)
    if (A.column[k] == 4) A.column[k] = 5;
  auto solver = make_solver("pcg_amg", 1e-8, 100);
  std::vector<double> x(A.rows, 0.0);
  try {
    solver->solve(A, smooth_rhs(A.rows), x);
    FAIL() << "a matrix without a diagonal entry was accepted";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("row 4"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace washout
