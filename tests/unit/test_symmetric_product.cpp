// The product from the upper triangle (engine/solvers/symmetric_product.hpp): the same y = A x
// as the full rows to round-off, the same bits on one thread or two, and the full rows used
// instead where the numbering has mixed so far that the blocks' buffers would not pay.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <random>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/row_sum.hpp"
#include "engine/solvers/solver_counters.hpp"
#include "engine/solvers/symmetric_product.hpp"

namespace washout {
namespace {

// A symmetric matrix with the PPE's pattern in 3D: each point of an n^3 grid coupled to its 26
// neighbours with weights symmetric in the pair, the diagonal their sum plus a margin. The rows
// are numbered through `order` (order[grid index] = row).
CsrMatrix stencil_matrix(int n, const std::vector<std::int32_t>& order) {
  const std::size_t rows = std::size_t(n) * n * n;
  std::vector<std::vector<std::pair<std::int32_t, double>>> entries(rows);
  auto grid = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int me = grid(i, j, k);
        double diagonal = 0.1;
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int ii = i + di, jj = j + dj, kk = k + dk;
              if ((di == 0 && dj == 0 && dk == 0) || ii < 0 || jj < 0 || kk < 0 || ii >= n ||
                  jj >= n || kk >= n)
                continue;
              const int other = grid(ii, jj, kk);
              const double c =
                  1.0 + 0.5 * std::sin(0.37 * (std::min(me, other) + 3.0 * std::max(me, other)));
              diagonal += c;
              entries[order[other]].emplace_back(order[me], -c);
            }
        entries[order[me]].emplace_back(order[me], diagonal);
      }
  CsrMatrix A;
  A.rows = rows;
  A.row_start.push_back(0);
  for (const auto& row : entries) {
    for (const auto& [column, value] : row) {
      A.column.push_back(column);
      A.value.push_back(value);
    }
    A.row_start.push_back(std::int64_t(A.value.size()));
  }
  return A;
}

std::vector<std::int32_t> identity_order(int n) {
  std::vector<std::int32_t> order(std::size_t(n) * n * n);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

std::vector<double> wavy(std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = std::sin(0.7 * double(i)) + 0.3 * std::cos(0.1 * i);
  return v;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double difference = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    difference = std::max(difference, std::abs(a[i] - b[i]));
  return difference;
}

double largest_magnitude(const std::vector<double>& a) {
  double m = 0.0;
  for (const double v : a) m = std::max(m, std::abs(v));
  return m;
}

// The row sum in four partial sums (row_sum.hpp) against the sum taken in long double, for rows
// of every length around the unrolled four, with terms of both signs and mixed magnitudes; and
// the gather it is given is the one it uses.
TEST(SparseRowSum, IsTheRowsSumToRoundOffForEveryLength) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> x(64), value(64);
  std::vector<std::int32_t> column(64);
  for (auto& v : x) v = uniform(random) * std::pow(10.0, 3.0 * uniform(random));
  double worst = 0.0;
  for (int length = 0; length <= 13; ++length)
    for (int trial = 0; trial < 50; ++trial) {
      const std::int64_t begin = trial % 5, end = begin + length;
      long double exact = 0.0L, scale = 0.0L;
      for (std::int64_t k = begin; k < end; ++k) {
        value[k] = uniform(random);
        column[k] = static_cast<std::int32_t>(random() % x.size());
        exact += static_cast<long double>(value[k]) * x[column[k]];
        scale += std::abs(static_cast<long double>(value[k]) * x[column[k]]);
      }
      const double sum = sparse_row_dot(value.data(), column.data(), begin, end, x.data());
      const double error = scale > 0 ? double(std::abs(sum - exact) / scale) : std::abs(sum);
      worst = std::max(worst, error);
      // Each term enters one of four sums of at most four terms, then three additions.
      EXPECT_LT(error, 8 * 1.2e-16) << "length " << length;
      const double doubled = sparse_row_sum(value.data(), column.data(), begin, end,
                                            [&](std::int32_t j) { return 2.0 * x[j]; });
      EXPECT_EQ(doubled, 2.0 * sum);  // exact: doubling commutes with every rounding
    }
  std::printf("largest error of a row sum, relative to the sum of |terms|: %.2e\n", worst);
}

// 13,824 rows in 14 blocks, 0.37 M non-zeros (threaded), each block reaching about n^2 rows
// beyond its end.
TEST(SymmetricProduct, MatchesTheFullRowsAndIsTheSameOnAnyThreadCount) {
  const int n = 24;
  const CsrMatrix A = stencil_matrix(n, identity_order(n));
  SymmetricProduct product;
  ASSERT_TRUE(product.build(A));
  EXPECT_EQ(product.upper_entries(), (A.nonzeros() - A.rows) / 2);
  const std::vector<double> x = wavy(A.rows);
  std::vector<double> full, one, two;
  A.multiply(x, full);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  product.multiply(x, one);
  omp_set_num_threads(2);
  product.multiply(x, two);
  omp_set_num_threads(threads);
  const double error = largest_difference(full, one) / largest_magnitude(full);
  std::printf(
      "%zu rows, %zu non-zeros: %zu upper entries, %zu beyond the blocks; "
      "max |y - y_full| / max |y_full| = %.2e\n",
      A.rows, A.nonzeros(), product.upper_entries(), product.spill_entries(), error);
  EXPECT_LT(error, 1e-14);  // the same sums in another order: a few ulps of the largest term
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)), 0);
  // 27 entries a row: 348 bytes a row in full rows, about 213 from the upper triangle (13 upper
  // entries, the diagonal, the buffer); the PPE's 50 entries a row save more.
  EXPECT_LT(product.product_bytes(), 0.65 * csr_product_bytes(A));
}

// The PPE's rows as the assembly writes them: the diagonal first, the neighbours in the lists'
// order (upper and lower columns mixed), and rows of a given pressure that hold their diagonal
// alone, here the last eight of every block of 1,024 rows and of the matrix. The triangle taken
// without a branch per entry (build()) must still hold every upper entry in place: the same
// product as the full rows, on one thread or two (a write past a block's last upper slot would
// land in the next block's, another thread's).
TEST(SymmetricProduct, RowsInAnyColumnOrderAndDiagonalOnlyRowsAtTheBlocksEnds) {
  const int n = 24;
  const CsrMatrix lattice = stencil_matrix(n, identity_order(n));
  const auto given = [&](std::size_t i) { return i % 1024 >= 1016 || i + 8 >= lattice.rows; };
  CsrMatrix A;
  A.rows = lattice.rows;
  A.row_start.push_back(0);
  std::mt19937 random(5);
  for (std::size_t i = 0; i < lattice.rows; ++i) {
    std::vector<std::pair<std::int32_t, double>> row;
    for (std::int64_t k = lattice.row_start[i]; k < lattice.row_start[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(lattice.column[k]);
      if (j == i || (!given(i) && !given(j))) row.emplace_back(lattice.column[k], lattice.value[k]);
    }
    const auto diagonal = std::find_if(row.begin(), row.end(), [&](const auto& entry) {
      return static_cast<std::size_t>(entry.first) == i;
    });
    std::iter_swap(row.begin(), diagonal);
    std::shuffle(row.begin() + 1, row.end(), random);
    for (const auto& [column, value] : row) {
      A.column.push_back(column);
      A.value.push_back(value);
    }
    A.row_start.push_back(std::int64_t(A.value.size()));
  }
  const std::vector<double> x = wavy(A.rows);
  std::vector<double> full, one, two;
  A.multiply(x, full);
  const int threads = omp_get_max_threads();
  SymmetricProduct product;
  omp_set_num_threads(2);
  ASSERT_TRUE(product.build(A));
  product.multiply(x, two);
  omp_set_num_threads(1);
  product.multiply(x, one);
  omp_set_num_threads(threads);
  EXPECT_EQ(product.upper_entries(), (A.nonzeros() - A.rows) / 2);
  const double error = largest_difference(full, two) / largest_magnitude(full);
  std::printf("%zu rows, %zu non-zeros, shuffled rows: max |y - y_full| / max |y_full| = %.2e\n",
              A.rows, A.nonzeros(), error);
  EXPECT_LT(error, 1e-14);
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)), 0);
}

// Fewer rows than a block: one block, no buffer beyond it.
TEST(SymmetricProduct, ASmallMatrixIsOneBlock) {
  const CsrMatrix A = stencil_matrix(6, identity_order(6));
  SymmetricProduct product;
  ASSERT_TRUE(product.build(A));
  EXPECT_EQ(product.spill_entries(), 0u);
  const std::vector<double> x = wavy(A.rows);
  std::vector<double> full, y;
  A.multiply(x, full);
  product.multiply(x, y);
  EXPECT_LT(largest_difference(full, y) / largest_magnitude(full), 1e-14);
}

// Rows numbered at random: a neighbour's row is anywhere, each of the 63 blocks' buffers would
// span the rest of the matrix (31 entries a row in all against 13 upper ones), and the product
// declines (the solver then multiplies by the full rows).
TEST(SymmetricProduct, DeclinesARandomNumbering) {
  const int n = 40;
  std::vector<std::int32_t> order = identity_order(n);
  std::mt19937 random(7);
  std::shuffle(order.begin(), order.end(), random);
  const CsrMatrix A = stencil_matrix(n, order);
  SymmetricProduct product;
  EXPECT_FALSE(product.build(A));
  EXPECT_FALSE(product.ready());
}

// CG reaches the same solution whichever product it takes: on the lattice numbering (upper
// triangle) and on a random one (full rows), the solutions agree to the solver's tolerance.
TEST(SymmetricProduct, ConjugateGradientSolvesTheSameSystemEitherWay) {
  const int n = 40;
  std::vector<std::int32_t> order = identity_order(n);
  std::mt19937 random(11);
  std::shuffle(order.begin(), order.end(), random);
  const CsrMatrix ordered = stencil_matrix(n, identity_order(n));
  const CsrMatrix shuffled = stencil_matrix(n, order);
  SymmetricProduct ordered_product, shuffled_product;
  ASSERT_TRUE(ordered_product.build(ordered));
  ASSERT_FALSE(shuffled_product.build(shuffled));
  const std::vector<double> b = wavy(ordered.rows);
  std::vector<double> b_shuffled(b.size());
  for (std::size_t g = 0; g < b.size(); ++g) b_shuffled[order[g]] = b[g];
  auto solver = make_pcg_solver(1e-10, 1000);
  std::vector<double> x, x_shuffled;
  const SolveReport a = solver->solve(ordered, b, x);
  auto other = make_pcg_solver(1e-10, 1000);
  const SolveReport c = other->solve(shuffled, b_shuffled, x_shuffled);
  ASSERT_TRUE(a.converged);
  ASSERT_TRUE(c.converged);
  double difference = 0.0;
  for (std::size_t g = 0; g < x.size(); ++g)
    difference = std::max(difference, std::abs(x[g] - x_shuffled[order[g]]));
  std::printf("iterations %d (upper triangle) and %d (full rows); max |x - x'| / max |x| = %.2e\n",
              a.iterations, c.iterations, difference / largest_magnitude(x));
  EXPECT_LT(difference, 1e-8 * largest_magnitude(x));
  EXPECT_LE(std::abs(a.iterations - c.iterations), 2);
  EXPECT_LT(relative_residual(ordered, b, x), 1e-10);
}

}  // namespace
}  // namespace washout
