// The Cholesky factor's solves by supernodes give the factor's own solution to rounding
// (engine/solvers/cholesky_factor_solve.hpp): the blocks below the supernodes' diagonals summed
// as dense blocks, in vectorised partial sums.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <random>
#include <vector>

#include "engine/solvers/cholesky_factor_solve.hpp"

namespace washout {
namespace {

// A 3D lattice laplacian with random positive couplings to the 26 neighbours and a diagonal a
// little above the row sum (as the coarse PPE systems: nearly singular, the graph of a 3D flow),
// in `blocks` disconnected pieces so that the elimination tree is a forest.
Eigen::SparseMatrix<double> lattice_system(int length, int side, int blocks, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coupling(0.1, 1.0);
  const int per_block = length * side * side, n = blocks * per_block;
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> diagonal(static_cast<std::size_t>(n), 1e-3);
  const auto index = [&](int b, int x, int y, int z) {
    return b * per_block + (x * side + y) * side + z;
  };
  for (int b = 0; b < blocks; ++b)
    for (int x = 0; x < length; ++x)
      for (int y = 0; y < side; ++y)
        for (int z = 0; z < side; ++z)
          for (int dx = 0; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dz = -1; dz <= 1; ++dz) {
                if (dx == 0 && (dy < 0 || (dy == 0 && dz <= 0))) continue;  // each pair once
                const int X = x + dx, Y = y + dy, Z = z + dz;
                if (X >= length || Y < 0 || Y >= side || Z < 0 || Z >= side) continue;
                const int i = index(b, x, y, z), j = index(b, X, Y, Z);
                const double c = coupling(random);
                entries.emplace_back(std::max(i, j), std::min(i, j), -c);
                diagonal[static_cast<std::size_t>(i)] += c;
                diagonal[static_cast<std::size_t>(j)] += c;
              }
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, diagonal[static_cast<std::size_t>(i)]);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;  // the lower triangle, which the factor reads
}

TEST(CholeskyFactorSolve, GivesTheFactorsOwnSolutionToRounding) {
  for (const int blocks : {1, 3}) {
    const Eigen::SparseMatrix<double> A = lattice_system(20, 9, blocks, 7u + blocks);
    CholeskyFactorSolve::Factor factor(A);
    ASSERT_EQ(factor.info(), Eigen::Success);
    std::mt19937 random(3);
    std::normal_distribution<double> normal;
    Eigen::VectorXd b(A.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = normal(random);
    b[5] = 0.0;  // a zero, which Eigen's forward loop skips
    const Eigen::VectorXd expected = factor.solve(b);
    CholeskyFactorSolve fast;
    fast.build(factor);
    Eigen::VectorXd x;
    fast.solve(b, x);
    // Solved, not only alike: the residual of the system (its condition number is about 1e4; a
    // column taken before one it needs would leave a residual of order 1).
    const Eigen::SparseMatrix<double> full = A.selfadjointView<Eigen::Lower>();
    const double residual = (full * x - b).norm() / b.norm();
    ASSERT_EQ(x.size(), expected.size());
    // Another order of a sum moves a solution by about its condition number times the
    // rounding, 1e4 x 1e-16 relative; a wrong entry of L or a column out of its turn, by far
    // more (order 1).
    const double difference =
        (x - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
    std::printf(
        "%d pieces: %zu rows, %zu supernodes (widest %zu), residual %.2e, from Eigen's solve "
        "%.2e\n",
        blocks, fast.rows(), fast.supernodes(), fast.widest_supernode(), residual, difference);
    EXPECT_LT(residual, 1e-10);
    EXPECT_LT(difference, 1e-10);
    // Supernodes wider than one column: the dense blocks are exercised.
    EXPECT_LT(fast.supernodes(), fast.rows() / 2);
    EXPECT_GT(fast.widest_supernode(), 8u);
  }
}

// The elimination tree cut in two groups and a top (the header's "Two threads"): on a system of
// the coarse PPE's size, both groups hold work and the longer path (top plus heavier group) is a
// clear saving on the whole; one thread gives the same bits as two, and a small factor stays
// whole.
TEST(CholeskyFactorSolve, TwoGroupsOfSubtreesTheSameBitsOnOneThreadAsOnTwo) {
  const Eigen::SparseMatrix<double> A = lattice_system(30, 10, 1, 11u);
  CholeskyFactorSolve::Factor factor(A);
  ASSERT_EQ(factor.info(), Eigen::Success);
  CholeskyFactorSolve fast;
  fast.build(factor);
  const auto groups = fast.group_entries();
  const double total = double(groups[0] + groups[1] + fast.top_entries());
  const double path = double(fast.top_entries() + std::max(groups[0], groups[1]));
  std::printf(
      "%zu rows, %.0f entries: groups %zu and %zu, top %zu; longer path %.2f of the whole\n",
      fast.rows(), total, groups[0], groups[1], fast.top_entries(), path / total);
  EXPECT_GT(groups[0], 0u);
  EXPECT_GT(groups[1], 0u);
  EXPECT_LT(path / total, 0.8);  // kWorthwhileCut

  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  Eigen::VectorXd b(A.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = normal(random);
  Eigen::VectorXd x1, x2;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  fast.solve(b, x1);
  omp_set_num_threads(2);
  fast.solve(b, x2);
  fast.solve(b, x2);  // the top's parts cleared after each solve: a second gives the same
  omp_set_num_threads(threads);
  EXPECT_EQ(x1, x2);
  const Eigen::VectorXd expected = factor.solve(b);
  const double difference =
      (x2 - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
  std::printf("from Eigen's solve %.2e\n", difference);
  EXPECT_LT(difference, 1e-10);

  const Eigen::SparseMatrix<double> small = lattice_system(6, 5, 1, 3u);
  CholeskyFactorSolve::Factor small_factor(small);
  CholeskyFactorSolve whole;
  whole.build(small_factor);
  EXPECT_EQ(whole.group_entries()[0] + whole.group_entries()[1], 0u);
}

}  // namespace
}  // namespace washout
