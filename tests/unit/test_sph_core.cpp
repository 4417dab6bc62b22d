// Kernel, neighbour search and SPH operators of METHOD.md on lattices.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "engine/core/cubic_spline_kernel.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"

namespace washout {
namespace {

// The kernel integrates to one: a fine quadrature of W over its support (2D rings, 3D shells).
TEST(Kernel, NormalisedIn2dAnd3d) {
  for (int dim : {2, 3}) {
    const CubicSplineKernel W(dim, 0.7);
    double integral = 0.0;
    const int steps = 20000;
    const double dr = 2.0 * 0.7 / steps;
    for (int k = 0; k < steps; ++k) {
      const double r = (k + 0.5) * dr;
      integral += W.value(r) * (dim == 2 ? 2 * M_PI * r : 4 * M_PI * r * r) * dr;
    }
    std::printf("dim %d: integral of W = %.8f\n", dim, integral);
    EXPECT_NEAR(integral, 1.0, 1e-6);  // quadrature error of the midpoint rule at this step
  }
}

// dW/dr against a central difference of W, and the r -> 0 limit of W'/r.
TEST(Kernel, DerivativeMatchesFiniteDifference) {
  const CubicSplineKernel W(3, 1.0);
  double worst = 0.0;
  for (double r = 0.01; r < 2.0; r += 0.0137) {
    const double fd = (W.value(r + 1e-6) - W.value(r - 1e-6)) / 2e-6;
    worst = std::max(worst, std::abs(fd - W.derivative(r)));
    EXPECT_NEAR(W.derivative_over_r(r) * r, W.derivative(r), 1e-12);
  }
  std::printf("max |dW/dr - finite difference| = %.2e\n", worst);
  EXPECT_LT(worst, 1e-7);
  EXPECT_EQ(W.value(2.0), 0.0);
  EXPECT_EQ(W.derivative(2.5), 0.0);
}

Particles random_particles(int dim, std::size_t n, double box, unsigned seed) {
  Particles p;
  p.dim = dim;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, box);
  for (std::size_t i = 0; i < n; ++i)
    p.add(ParticleKind::Fluid, Vec3(u(rng), u(rng), dim == 3 ? u(rng) : 0.0), Vec3::Zero(), -1);
  return p;
}

// The cell list finds exactly the pairs a brute-force search finds, with and without
// periodic directions.
TEST(NeighborGrid, MatchesBruteForce) {
  for (int dim : {2, 3})
    for (bool periodic : {false, true}) {
      const double box = 1.0, radius = 0.11;
      Particles p = random_particles(dim, dim == 2 ? 1500 : 3000, box, 7);
      PeriodicBox pb;
      if (periodic)
        for (int a = 0; a < dim; ++a) pb.periodic[a] = true, pb.lower[a] = 0, pb.length[a] = box;
      NeighborGrid grid;
      grid.build(p, radius, pb);
      NeighborList list;
      grid.build_list(p, p.size(), radius, list);
      std::size_t mismatches = 0, pairs = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        std::set<std::uint32_t> found(list.index.begin() + list.offset[i],
                                      list.index.begin() + list.offset[i + 1]);
        for (std::size_t j = 0; j < p.size(); ++j) {
          if (j == i) continue;
          double d[3] = {p.position[0][i] - p.position[0][j], p.position[1][i] - p.position[1][j],
                         p.position[2][i] - p.position[2][j]};
          pb.minimum_image(d);
          const bool near = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < radius * radius;
          pairs += near;
          mismatches += near != (found.count(static_cast<std::uint32_t>(j)) == 1);
        }
      }
      std::printf("dim %d periodic %d: %zu pairs, %zu mismatches\n", dim, periodic, pairs,
                  mismatches);
      EXPECT_EQ(mismatches, 0u);
      EXPECT_GT(pairs, 1000u);
    }
}

// A perfect lattice with the operators' lattice normalisation: the density of an interior
// particle is rho0, the gradient of a linear field and the laplacian of a quadratic field are
// exact at interior particles (to round-off), and close after a random perturbation.
struct LatticeFixture {
  int dim;
  double d0 = 0.01;
  Particles p;
  SphContext ctx;
  NeighborList list;
  LatticeFixture(int dim_, double jitter) : dim(dim_), ctx(dim_, 0.01, 1.2, 1000.0, PeriodicBox{}) {
    p.dim = dim;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-jitter * d0, jitter * d0);
    const int n = dim == 2 ? 16 : 10;
    for (int k = 0; k < (dim == 3 ? n : 1); ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          p.add(ParticleKind::Fluid,
                Vec3((i + 0.5) * d0 + u(rng), (j + 0.5) * d0 + u(rng),
                     dim == 3 ? (k + 0.5) * d0 + u(rng) : 0),
                Vec3::Zero(), -1);
    NeighborGrid grid;
    grid.build(p, 2 * ctx.h, ctx.periodic);
    grid.build_list(p, p.size(), 2 * ctx.h, list);
  }
  bool interior(std::size_t i) const {
    for (int a = 0; a < dim; ++a) {
      const double x = p.position[a][i], L = (dim == 2 ? 16 : 10) * d0;
      if (x < 3 * d0 || x > L - 3 * d0) return false;
    }
    return true;
  }
};

void check_operators(int dim, double jitter, double tol_grad, double tol_lap) {
  LatticeFixture f(dim, jitter);
  const Vec3 a(1.5, -2.0, 0.7);  // f = a.x, grad f = a; g = |x|^2, lap g = 2 dim
  double grad_err = 0, lap_err = 0, rho_err = 0;
  for (std::size_t i = 0; i < f.p.size(); ++i) {
    if (!f.interior(i)) continue;
    double grad[3] = {0, 0, 0}, lap = 0, rho = f.ctx.mass * f.ctx.kernel.value(0);
    const Vec3 xi = f.p.x(i);
    for (std::uint64_t k = f.list.offset[i]; k < f.list.offset[i + 1]; ++k) {
      const std::size_t j = f.list.index[k];
      const Vec3 xj = f.p.x(j), d = xi - xj;
      const double r = d.norm();
      rho += f.ctx.mass * f.ctx.kernel.value(r);
      // difference gradient: sum V (f_j - f_i) grad W_ij
      const double g = f.ctx.gradient_correction * f.ctx.volume * f.ctx.kernel.derivative_over_r(r);
      for (int c = 0; c < dim; ++c) grad[c] += g * (a.dot(xj) - a.dot(xi)) * d[c];
      // laplacian: sum V 2 (r . grad W)/(r^2 + eta^2) (g_i - g_j)
      lap += f.ctx.laplacian_correction * f.ctx.volume * 2 * f.ctx.kernel.derivative(r) * r /
             (r * r + f.ctx.eta2) * (xi.squaredNorm() - xj.squaredNorm());
    }
    for (int c = 0; c < dim; ++c)
      grad_err = std::max(grad_err, std::abs(grad[c] - a[c]) / a.norm());
    lap_err = std::max(lap_err, std::abs(lap - 2 * dim) / (2 * dim));
    rho_err = std::max(rho_err, std::abs(rho / f.ctx.full_support_density - 1));
  }
  std::printf(
      "dim %d jitter %.2f d0: gradient error %.2e, laplacian error %.2e, density error %.2e\n", dim,
      jitter, grad_err, lap_err, rho_err);
  EXPECT_LT(grad_err, tol_grad);
  EXPECT_LT(lap_err, tol_lap);
  if (jitter == 0) {
    EXPECT_LT(rho_err, 1e-12);
  }
}

TEST(Operators, ExactOnLattice2d) { check_operators(2, 0.0, 1e-12, 1e-12); }
TEST(Operators, ExactOnLattice3d) { check_operators(3, 0.0, 1e-12, 1e-12); }
// With particles displaced by up to 1 % of d0 the sums lose their lattice symmetry. The
// gradient error grows like the jitter (0.9 x jitter measured); the laplacian of a quadratic
// field is far more sensitive, since Brookshaw's form is not consistent on disordered
// particles (17 x jitter measured in 2D, 6 x in 3D). Bounds: about twice what was measured.
TEST(Operators, PerturbedLattice2d) { check_operators(2, 0.01, 0.02, 0.4); }
TEST(Operators, PerturbedLattice3d) { check_operators(3, 0.01, 0.02, 0.15); }

}  // namespace
}  // namespace washout
