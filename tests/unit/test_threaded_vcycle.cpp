// The threaded V-cycle (engine/solvers/threaded_vcycle.hpp) on BoomerAMG's hierarchy: with one
// Gauss-Seidel block (in double precision) it is hypre's own cycle; with several it stays a
// symmetric operator (as CG needs), gives the same result on any number of threads, and
// preconditions as well; with its matrices in single precision (the default) it is the double
// cycle to float rounding, still symmetric, and CG takes as many iterations.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/preconditioner.hpp"
#include "engine/solvers/threaded_vcycle.hpp"

namespace washout {
namespace {

// -lap u on an n^3 grid with Dirichlet walls, with a variable coefficient (an SPD matrix less
// regular than the plain stencil, as the PPE's is).
CsrMatrix variable_laplacian(int n) {
  CsrMatrix A;
  A.rows = std::size_t(n) * n * n;
  A.row_start.push_back(0);
  auto index = [n](int i, int j, int k) { return std::int32_t((k * n + j) * n + i); };
  auto coefficient = [](int a, int b) { return 1.0 + 0.5 * std::sin(0.37 * (a + 3 * b)); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int me = index(i, j, k);
        double diagonal = 0.0;
        const std::size_t diagonal_slot = A.value.size();
        A.column.push_back(me);
        A.value.push_back(0.0);
        const int step[6][3] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
        for (const auto& s : step) {
          const int ii = i + s[0], jj = j + s[1], kk = k + s[2];
          const bool inside = ii >= 0 && jj >= 0 && kk >= 0 && ii < n && jj < n && kk < n;
          const double c =
              inside ? coefficient(me, index(ii, jj, kk)) + coefficient(index(ii, jj, kk), me)
                     : 2.0;
          diagonal += c;
          if (!inside) continue;
          A.column.push_back(index(ii, jj, kk));
          A.value.push_back(-c);
        }
        A.value[diagonal_slot] = diagonal;
        A.row_start.push_back(std::int64_t(A.value.size()));
      }
  return A;
}

std::vector<double> wavy(std::size_t n, double f) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = std::sin(f * double(i)) + 0.3 * std::cos(0.1 * i);
  return v;
}

std::vector<double> cycle(const CsrMatrix& A, AmgOptions options, const std::vector<double>& r) {
  auto amg = make_boomeramg_preconditioner(options);
  amg->prepare(A, false);
  std::vector<double> z;
  amg->apply(r, z);
  return z;
}

double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0, s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d += (a[i] - b[i]) * (a[i] - b[i]);
    s += b[i] * b[i];
  }
  return std::sqrt(d / s);
}

TEST(ThreadedVCycle, OneBlockIsHypresCycle) {
  const CsrMatrix A = variable_laplacian(24);  // 13,824 rows
  const auto r = wavy(A.rows, 0.7);
  AmgOptions hypre;
  hypre.threaded_cycle = false;
  AmgOptions one_block;
  one_block.cycle_block_rows = A.rows;
  one_block.single_precision_cycle = false;
  const double difference = relative_difference(cycle(A, one_block, r), cycle(A, hypre, r));
  std::printf("one block against hypre's V-cycle: relative difference %.2e\n", difference);
  EXPECT_LT(difference, 1e-10);  // the same sweeps; only the rounding of the coarsest solve
}

TEST(ThreadedVCycle, SweepBlocksAreSharedEquallyByTwoOrFourThreads) {
  constexpr std::size_t block = ThreadedVCycle::kDefaultBlockRows;
  // The same-case dam break at a/40: 64,000 rows were three blocks, one thread doing two.
  EXPECT_EQ(ThreadedVCycle::sweep_blocks(64000, block), 4u);
  std::size_t smallest = block, largest = 0;
  for (std::size_t rows = 1000; rows < 3000000; rows = rows * 21 / 20 + 7) {
    const std::size_t blocks = ThreadedVCycle::sweep_blocks(rows, block);
    if (rows < 2 * block) {
      EXPECT_EQ(blocks, 1u) << rows << " rows";
      continue;
    }
    EXPECT_EQ(blocks % 4, 0u) << rows << " rows";
    smallest = std::min(smallest, rows / blocks);
    largest = std::max(largest, rows / blocks);
  }
  std::printf("rows a block from two blocks' worth up: %zu to %zu (block_rows %zu)\n", smallest,
              largest, block);
  // Rounding the count up splits at most twice as fine (two blocks' worth in four); a count of
  // four or more leaves at most a quarter block over (4 blocks' worth plus 0.99 in four).
  EXPECT_GE(smallest, block / 2);
  EXPECT_LT(largest, block + block / 4);
}

TEST(ThreadedVCycle, BlocksKeepTheCycleSymmetricAndThreadIndependent) {
  const CsrMatrix A = variable_laplacian(24);
  AmgOptions blocks;
  blocks.cycle_block_rows = A.rows / 6;  // six blocks' worth: eight blocks
  const auto u = wavy(A.rows, 0.7), v = wavy(A.rows, 1.3);
  const auto Mu = cycle(A, blocks, u), Mv = cycle(A, blocks, v);
  const double uMv = std::inner_product(u.begin(), u.end(), Mv.begin(), 0.0);
  const double vMu = std::inner_product(v.begin(), v.end(), Mu.begin(), 0.0);
  std::printf("eight blocks: u.M^-1 v = %.12e, v.M^-1 u = %.12e\n", uMv, vMu);
  EXPECT_NEAR(uMv, vMu, 1e-10 * std::abs(uMv));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one_thread = cycle(A, blocks, u);
  omp_set_num_threads(std::max(2, threads));
  const auto more_threads = cycle(A, blocks, u);
  omp_set_num_threads(threads);
  EXPECT_EQ(one_thread, more_threads);  // bit for bit
  EXPECT_EQ(one_thread, Mu);
}

TEST(ThreadedVCycle, BlocksPreconditionAsWellAsHypresCycle) {
  const CsrMatrix A = variable_laplacian(30);  // 27,000 rows
  const auto b = wavy(A.rows, 0.7);
  auto iterations = [&](AmgOptions options) {
    auto solver = make_amg_pcg_solver(1e-8, 500, options);
    std::vector<double> x(A.rows, 0.0);
    const auto report = solver->solve(A, b, x);
    EXPECT_TRUE(report.converged);
    EXPECT_LT(relative_residual(A, b, x), 1e-8);
    return report.iterations;
  };
  AmgOptions hypre, blocks;
  hypre.threaded_cycle = false;
  blocks.cycle_block_rows = A.rows / 8;
  const int with_hypre = iterations(hypre), with_blocks = iterations(blocks);
  std::printf("CG iterations to 1e-8: hypre's cycle %d, eight blocks %d\n", with_hypre,
              with_blocks);
  EXPECT_LE(with_blocks, with_hypre + 2);
}

TEST(ThreadedVCycle, SinglePrecisionIsTheDoubleCycleToFloatRounding) {
  const CsrMatrix A = variable_laplacian(24);
  AmgOptions single, exact;
  single.cycle_block_rows = exact.cycle_block_rows = A.rows / 6;
  exact.single_precision_cycle = false;
  ASSERT_TRUE(single.single_precision_cycle);  // the default
  const auto u = wavy(A.rows, 0.7), v = wavy(A.rows, 1.3);
  const auto Mu = cycle(A, single, u), Mv = cycle(A, single, v);
  // The matrices' values rounded to 24 bits (relative 6e-8 each): the cycle's result moves by
  // about that times the cycle's amplification, far below what a preconditioner notices.
  const double difference = relative_difference(Mu, cycle(A, exact, u));
  std::printf("single against double precision cycle: relative difference %.2e\n", difference);
  EXPECT_GT(difference, 0.0);  // the values really are rounded
  EXPECT_LT(difference, 1e-5);
  // Both sweeps read the same rounded matrix and R = P^T holds for the rounded P: symmetric to
  // the double sums' rounding.
  const double uMv = std::inner_product(u.begin(), u.end(), Mv.begin(), 0.0);
  const double vMu = std::inner_product(v.begin(), v.end(), Mu.begin(), 0.0);
  std::printf("single precision: u.M^-1 v = %.12e, v.M^-1 u = %.12e\n", uMv, vMu);
  EXPECT_NEAR(uMv, vMu, 1e-10 * std::abs(uMv));
}

TEST(ThreadedVCycle, SinglePrecisionPreconditionsAsWellAsDouble) {
  const CsrMatrix A = variable_laplacian(30);
  const auto b = wavy(A.rows, 0.7);
  auto solve = [&](bool single_precision, std::vector<double>& x) {
    AmgOptions options;
    options.cycle_block_rows = A.rows / 8;
    options.single_precision_cycle = single_precision;
    auto solver = make_amg_pcg_solver(1e-10, 500, options);
    x.assign(A.rows, 0.0);
    const auto report = solver->solve(A, b, x);
    EXPECT_TRUE(report.converged);
    // CG itself is in double: the tolerance is met on the true matrix, not the rounded one.
    EXPECT_LT(relative_residual(A, b, x), 1e-10);
    return report.iterations;
  };
  std::vector<double> x_single, x_double;
  const int with_single = solve(true, x_single), with_double = solve(false, x_double);
  const double difference = relative_difference(x_single, x_double);
  std::printf(
      "CG iterations to 1e-10: single precision cycle %d, double %d; solutions differ by "
      "%.2e\n",
      with_single, with_double, difference);
  EXPECT_LE(with_single, with_double + 1);
  EXPECT_LT(difference, 1e-8);
}

}  // namespace
}  // namespace washout
