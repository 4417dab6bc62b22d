// The PPE matrix of METHOD.md step 2 and every solver against a manufactured solution:
// P = sin(pi s_x) sin(pi s_y) on a lattice whose outer ring is free surface (P = 0), where
// s runs from 0 on the ring to 1 on the opposite ring, so lap P = -(pi/L)^2 * 2 P.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"
#include "engine/solvers/linear_solver.hpp"

namespace washout {
namespace {

// Fluid particles at rest on a lattice (optionally offset per particle), neighbour list built,
// densities at rho0: the inputs of assemble_pressure_poisson.
struct LatticeSystem {
  SphContext ctx;
  Particles p;
  NeighborList list;
  FluidWork work;
  LatticeSystem(int n, double d0, double (*offset_x)(int, int))
      : ctx(2, d0, 1.2, 1000.0, PeriodicBox{}) {
    p.dim = 2;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        p.add(ParticleKind::Fluid, Vec3((i + 0.5) * d0 + offset_x(i, j), (j + 0.5) * d0, 0),
              Vec3::Zero(), -1);
    NeighborGrid grid;
    grid.build(p, 2 * ctx.h, ctx.periodic);
    grid.build_list(p, p.size(), 2 * ctx.h, list);
    for (int a = 0; a < 3; ++a) work.u_star[a].assign(p.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) p.density[i] = ctx.rho0;
    work.free_surface.assign(p.size(), 0);
  }
};

double no_offset(int, int) { return 0.0; }
double irregular_offset(int i, int j) { return 0.003 * ((i * 7 + j * 3) % 5); }

TEST(PressurePoisson, ManufacturedSolutionEverySolver) {
  for (int n : {20, 40}) {
    const double d0 = 1.0 / n;
    LatticeSystem sys(n, d0, no_offset);
    auto& [ctx, p, list, work] = sys;
    const double x0 = 0.5 * d0, L = 1.0 - d0;  // ring to ring
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double x = p.position[0][i], y = p.position[1][i];
      work.free_surface[i] = x < d0 || y < d0 || x > 1 - d0 || y > 1 - d0;
    }
    const auto stats =
        assemble_pressure_poisson(ctx, list, p, Vec3::Zero(), 0.0, 1e-3, false, work);
    EXPECT_EQ(stats.pinned_components, 0u);
    // Rows read sum_j c_ij (P_i - P_j) = -lap P: put the analytic laplacian on the right.
    std::vector<double> exact(stats.unknowns);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const int row = work.unknown[i];
      if (row < 0) continue;
      const double sx = (p.position[0][i] - x0) / L, sy = (p.position[1][i] - x0) / L;
      exact[row] = std::sin(std::numbers::pi * sx) * std::sin(std::numbers::pi * sy);
      work.rhs[row] = 2 * std::pow(std::numbers::pi / L, 2) * exact[row];
    }
    for (const char* name : {"cholmod", "pcg", "pcg_amg"}) {
      auto solver = make_solver(name, 1e-10, 5000);
      std::vector<double> x(stats.unknowns, 0.0);
      const auto report = solver->solve(work.matrix, work.rhs, x);
      double err = 0;
      for (std::size_t k = 0; k < x.size(); ++k) err = std::max(err, std::abs(x[k] - exact[k]));
      std::printf("n = %d, %s: %d iterations, residual %.1e, max error %.2e\n", n, name,
                  report.iterations, report.relative_residual, err);
      EXPECT_TRUE(report.converged);
      EXPECT_LT(report.relative_residual, 1e-9);
      // The Dirichlet ring is imposed through a truncated kernel support, so the error falls
      // between first and second order: 0.28 d0 at n = 20, 0.21 d0 at n = 40 measured.
      EXPECT_LT(err, 0.5 * d0);
    }
  }
}

// The assembled matrix is symmetric with a positive diagonal: what CHOLMOD and CG require.
TEST(PressurePoisson, MatrixIsSymmetric) {
  LatticeSystem sys(12, 0.05, irregular_offset);
  auto& [ctx, p, list, work] = sys;
  for (std::size_t i = 0; i < 12; ++i) work.free_surface[i] = 1;  // bottom row: Dirichlet
  assemble_pressure_poisson(ctx, list, p, Vec3::Zero(), 0.0, 1e-3, false, work);
  const CsrMatrix& A = work.matrix;
  double asymmetry = 0;
  for (std::size_t r = 0; r < A.rows; ++r) {
    EXPECT_GT(A.value[A.row_start[r]], 0.0);
    for (std::int64_t k = A.row_start[r] + 1; k < A.row_start[r + 1]; ++k) {
      const int c = A.column[k];
      double transposed = 0;
      for (std::int64_t m = A.row_start[c]; m < A.row_start[c + 1]; ++m)
        if (A.column[m] == static_cast<int>(r)) transposed = A.value[m];
      asymmetry = std::max(asymmetry, std::abs(A.value[k] - transposed));
    }
  }
  std::printf("max |A_ij - A_ji| = %.2e\n", asymmetry);
  EXPECT_LT(asymmetry, 1e-12 * A.value[0]);
}

// The corrector's symmetric gradient is the difference form plus 2 P_i S_i, S_i = sum_j V grad
// W_ij. A unit pressure at particle i alone changes the velocities of i and of its neighbours; the
// divergence at i that results is the corrector's own diagonal. The two forms' diagonals differ
// by 2 |S_i|^2, zero inside and large where the support is cut (a block's edges): the matrix
// assembled for the symmetric form must differ from the one for the difference form by exactly
// that, so that the pressure solved for is the one the corrector will apply (ppe_matrix.cpp).
// With symmetric_kernel = "wendland" the symmetric form's pair force has its own kernel K: it is
// the difference form in K plus 2 P_i S_i^K, and the divergence (in W) sees the latter as
// 2 S_i . S_i^K, which is what the diagonal gains.
void check_zero_order_term_on_the_diagonal(bool wendland) {
  LatticeSystem sys(10, 0.05, irregular_offset);
  auto& [ctx, p, list, work] = sys;
  if (wendland) ctx.use_wendland_symmetric_gradient();
  for (std::size_t i = 0; i < 10; ++i) work.free_surface[i] = 1;  // bottom row: Dirichlet
  assemble_pressure_poisson(ctx, list, p, Vec3::Zero(), 0.0, 1e-3, false, work);
  const std::vector<double> difference_diagonal = [&] {
    std::vector<double> d(work.matrix.rows);
    for (std::size_t r = 0; r < d.size(); ++r) d[r] = work.matrix.value[work.matrix.row_start[r]];
    return d;
  }();
  assemble_pressure_poisson(ctx, list, p, Vec3::Zero(), 0.0, 1e-3, false, work,
                            WallConditions::none(), true);
  // The divergence at i of the velocity change -grad(e_i) under either form (dt / rho0 = 1),
  // both forms with the symmetric gradient's kernel.
  const auto own_divergence = [&](std::size_t i, bool symmetric) {
    std::vector<std::array<double, 3>> du(p.size(), {0, 0, 0});
    for (std::size_t k = 0; k < p.size(); ++k) {
      const auto unit = [&](const NeighborPair& q) { return q.j == i ? 1.0 : 0.0; };
      double grad[3] = {0, 0, 0};
      const double own = k == i ? 1.0 : 0.0;
      if (symmetric) {
        symmetric_gradient(ctx, list, p, k, own, unit, grad);
      } else {
        for_each_neighbor(ctx, list, p, k, [&](const NeighborPair& q) {
          const double f = ctx.symmetric_gradient_weight(q.r) * (unit(q) - own);
          for (int a = 0; a < ctx.dim; ++a) grad[a] += f * q.d[a];
        });
      }
      for (int a = 0; a < 2; ++a) du[k][a] = -grad[a];
    }
    return divergence(ctx, list, p, i, du[i].data(), [&](const NeighborPair& q, double u[3]) {
      for (int a = 0; a < 3; ++a) u[a] = du[q.j][a];
    });
  };
  // The diagonal holds the difference where it is positive; where S_i and S_i^K point apart
  // (small, inside an irregular block) it holds nothing, which keeps the matrix definite.
  double largest = 0.0, worst = 0.0, left_out = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int row = work.unknown[i];
    if (row < 0) continue;
    const double added = work.matrix.value[work.matrix.row_start[row]] - difference_diagonal[row];
    const double own_difference = own_divergence(i, true) - own_divergence(i, false);
    largest = std::max(largest, added / difference_diagonal[row]);
    worst =
        std::max(worst, std::abs(added - std::max(0.0, own_difference)) / difference_diagonal[row]);
    left_out = std::max(left_out, -own_difference / difference_diagonal[row]);
  }
  std::printf(
      "%s: the zero-order term adds up to %.1f %% to a diagonal; it matches the corrector's "
      "own-divergence difference to %.1e of the diagonal (negative ones left out: at most "
      "%.2f %% of a diagonal)\n",
      wendland ? "Wendland pair force" : "cubic spline", 100 * largest, worst, 100 * left_out);
  EXPECT_GT(largest, 0.05);  // the block's edges: a cut support
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(left_out, 0.01);  // 0 with the cubic spline (2 |S_i|^2 >= 0)
}

TEST(PressurePoisson, SymmetricGradientsZeroOrderTermIsOnTheDiagonal) {
  check_zero_order_term_on_the_diagonal(false);
  check_zero_order_term_on_the_diagonal(true);
}

// With stable rows (what pcg_amg gets) every fluid particle keeps row i, and a particle whose
// pressure is given takes an identity row: the system is the compact one with decoupled rows
// added, so the same pressures come out of it.
TEST(PressurePoisson, StableRowsAddIdentityRowsAndChangeNoPressure) {
  LatticeSystem sys(12, 0.05, irregular_offset);
  auto& [ctx, p, list, work] = sys;
  for (std::size_t i = 0; i < 12; ++i) work.free_surface[i] = 1;  // bottom row: P = 0 given
  for (std::size_t i = 0; i < p.size(); ++i)
    work.u_star[0][i] = std::sin(7.0 * p.position[0][i]) * std::cos(5.0 * p.position[1][i]);
  const auto solve = [&](bool stable) {
    const auto stats = assemble_pressure_poisson(ctx, list, p, Vec3::Zero(), 0.05, 1e-3, false,
                                                 work, WallConditions::none(), false, stable);
    EXPECT_EQ(stats.unknowns, p.size() - 12);
    EXPECT_EQ(work.matrix.rows, stable ? p.size() : p.size() - 12);
    auto solver = make_solver("pcg_amg", 1e-12, 1000);
    std::vector<double> x(work.matrix.rows, 0.0);
    EXPECT_TRUE(solver->solve(work.matrix, work.rhs, x).converged);
    work.solution = x;
    scatter_pressure(work, p);
    return p.pressure;
  };
  const std::vector<double> compact = solve(false);
  const std::vector<double> stable = solve(true);
  const CsrMatrix& A = work.matrix;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i < 12) {  // the given row: P_i = 0, nothing else
      EXPECT_EQ(work.unknown[i], -1);
      EXPECT_EQ(A.row_start[i + 1] - A.row_start[i], 1);
      EXPECT_EQ(A.column[A.row_start[i]], static_cast<std::int32_t>(i));
      EXPECT_EQ(A.value[A.row_start[i]], 1.0);
      EXPECT_EQ(work.rhs[i], 0.0);
    } else {
      EXPECT_EQ(work.unknown[i], static_cast<std::int32_t>(i));
    }
  }
  double scale = 0, difference = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    scale = std::max(scale, std::abs(compact[i]));
    difference = std::max(difference, std::abs(stable[i] - compact[i]));
  }
  std::printf("largest pressure %.3e, stable - compact rows %.1e\n", scale, difference);
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(difference, 1e-9 * scale);
}

}  // namespace
}  // namespace washout
