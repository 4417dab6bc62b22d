// The pressure gradient normalised by each particle's own neighbours
// (engine/fluid/gradient_scale.cpp). The lattice normalisation makes the gradient exact on the
// initial lattice only; in the disordered arrangement a flow leaves, the gradient of a linear
// pressure comes out a few per cent too large, and at rest the pressure then settles that much
// too low. The scale must leave the lattice alone, make the gradient right on a disordered
// arrangement, reach the band below the free surface from the full supports beside it, and keep
// the symmetric form's pair force antisymmetric.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/core/sph_operators.hpp"
#include "support/fluid_block.hpp"

namespace washout {
namespace {

// Moves every particle by up to `amplitude` d0 in each direction (a fixed pseudo-random
// sequence), then lists the neighbours again.
void jitter(testing::FluidBlock& b, double amplitude) {
  std::uint64_t state = 12345;
  const auto next = [&]() {  // uniform in [-1, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / static_cast<double>(1ULL << 52) - 1.0;
  };
  for (std::size_t i = 0; i < b.p.fluid_count; ++i)
    for (int a = 0; a < 2; ++a)
      b.p.position[a][i] = b.ctx.periodic.wrap(b.p.position[a][i] + amplitude * b.kD0 * next(), a);
  NeighborGrid grid;
  grid.build(b.p, 2 * b.ctx.h, b.ctx.periodic);
  grid.build_list(b.p, b.p.size(), 2 * b.ctx.h, b.list);
  compute_summation_density(b.ctx, b.list, b.p);
}

// The symmetric gradient of particle i with the pair factor of the scale (or without).
Vec3 symmetric_gradient_of(const testing::FluidBlock& b, std::size_t i, bool scaled) {
  const std::size_t n = b.p.fluid_count;
  double grad[3];
  symmetric_gradient(
      b.ctx, b.list, b.p, i, b.p.pressure[i],
      [&](const NeighborPair& q) { return b.p.pressure[q.j]; },
      [&](const NeighborPair& q) { return scaled ? gradient_pair_scale(b.work, n, i, q.j) : 1.0; },
      grad);
  return Vec3(grad[0], grad[1], grad[2]);
}

TEST(GradientScale, LeavesTheLatticeAlone) {
  testing::FluidBlock b(16, 16, 0, true, true);
  b.work.free_surface.assign(b.p.fluid_count, 0);
  compute_gradient_scale(b.ctx, b.list, b.p, true, b.work);
  double worst = 0;
  for (double s : b.work.gradient_scale) worst = std::max(worst, std::abs(s - 1.0));
  std::printf("periodic lattice: largest |s - 1| = %.1e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

// A disordered arrangement (each particle moved by up to 0.2 d0) under a linear pressure
// P = rho0 g (Y - y): the interior's mean difference-form gradient against the exact rho0 g. (The
// difference form: on a random arrangement the symmetric form's zero-order term 2 P_i S_i is as
// large as the bias itself; in a flow the particles settle where it vanishes.)
TEST(GradientScale, MakesTheGradientOfALinearPressureRightOnADisorderedArrangement) {
  testing::FluidBlock b(24, 24, 0, false, false);
  jitter(b, 0.2);
  const double slope = 9810.0;
  for (std::size_t i = 0; i < b.p.fluid_count; ++i)
    b.p.pressure[i] = slope * (0.3 - b.p.position[1][i]);
  b.work.free_surface.assign(b.p.fluid_count, 0);
  compute_gradient_scale(b.ctx, b.list, b.p, false, b.work);
  double lattice = 0, particle = 0, spread = 0;
  int count = 0;
  for (std::size_t i = 0; i < b.p.fluid_count; ++i) {
    const double x = b.p.position[0][i], y = b.p.position[1][i];
    if (x < 0.05 || x > 0.19 || y < 0.05 || y > 0.19) continue;  // full supports only
    double grad[3];
    difference_gradient(
        b.ctx, b.list, b.p, i, b.p.pressure[i],
        [&](const NeighborPair& q) { return b.p.pressure[q.j]; }, grad);
    const double e = -grad[1] / slope - 1.0,
                 scaled = -grad[1] * b.work.gradient_scale[i] / slope - 1.0;
    lattice += e, particle += scaled, spread += scaled * scaled;
    ++count;
  }
  lattice /= count, particle /= count, spread = std::sqrt(spread / count);
  std::printf(
      "disordered block, %d interior particles: mean gradient error %+.2f %% with the "
      "lattice normalisation, %+.3f %% with the particle's (RMS %.2f %%)\n",
      count, 100 * lattice, 100 * particle, 100 * spread);
  EXPECT_GT(std::abs(lattice), 0.005);  // the arrangement's bias this test is about
  EXPECT_LT(std::abs(particle), 0.1 * std::abs(lattice));
}

// The top row is the free surface: the rows within a support below it (cut supports) take the
// mean scale of their neighbours with full supports, not their own low moment, and the surface
// row the mean of those.
TEST(GradientScale, TheBandBelowTheSurfaceTakesItsNeighboursScale) {
  testing::FluidBlock b(20, 16, 0, true, false);
  jitter(b, 0.1);
  const std::size_t n = b.p.fluid_count;
  b.work.free_surface.assign(n, 0);
  double top = 0;
  for (std::size_t i = 0; i < n; ++i) top = std::max(top, b.p.position[1][i]);
  for (std::size_t i = 0; i < n; ++i)
    if (b.p.position[1][i] > top - 0.6 * b.kD0) b.work.free_surface[i] = FluidWork::kSurface;
  compute_gradient_scale(b.ctx, b.list, b.p, true, b.work);
  const auto& level = b.work.gradient_scale_level;
  int band = 0, right = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (level[i] == 1 || b.p.position[1][i] < 0.04) continue;
    ++band;
    double sum = 0;
    int count = 0;
    for (std::uint64_t k = b.list.offset[i]; k < b.list.offset[i + 1]; ++k)
      if (b.list.index[k] < n && level[b.list.index[k]] == level[i] - 1)
        sum += b.work.gradient_scale[b.list.index[k]], ++count;
    const double expected = count > 0 ? sum / count : 1.0;
    if (std::abs(b.work.gradient_scale[i] - expected) < 1e-14 && count > 0) ++right;
  }
  std::printf(
      "band and surface: %d particles, %d with the mean scale of their neighbours one "
      "level further in\n",
      band, right);
  EXPECT_EQ(band, 60);  // the surface row and the two below it
  EXPECT_EQ(right, band);
}

// The pair factor (s_i + s_j)/2 is symmetric in i and j: on a periodic block the pair forces
// cancel and the total force sum_i V <grad P>_i vanishes, as without the scale.
TEST(GradientScale, KeepsTheSymmetricFormsMomentumConservation) {
  testing::FluidBlock b(16, 16, 0, true, true);
  jitter(b, 0.2);
  for (std::size_t i = 0; i < b.p.fluid_count; ++i)
    b.p.pressure[i] =
        1000.0 * (1.0 + std::sin(40.0 * b.p.position[0][i]) * std::cos(30.0 * b.p.position[1][i]));
  b.work.free_surface.assign(b.p.fluid_count, 0);
  compute_gradient_scale(b.ctx, b.list, b.p, true, b.work);
  Vec3 total = Vec3::Zero();
  double largest = 0;
  for (std::size_t i = 0; i < b.p.fluid_count; ++i) {
    const Vec3 g = symmetric_gradient_of(b, i, true);
    total += g;
    largest = std::max(largest, g.norm());
  }
  std::printf("periodic disordered block: |sum of gradients| / largest = %.1e\n",
              total.norm() / largest);
  EXPECT_LT(total.norm(), 1e-10 * largest * b.p.fluid_count);
}

// The step takes the moments in the density's walk (one walk over the pairs instead of two,
// compute_summation_density_and_gradient_moment): the same densities and moments, to the bit, as
// the two walks of their own, with the cubic spline and with the Wendland shape of 3D runs, on a
// disordered block on a floor (moments up to 0.5 off 1 at its open top: a wrong term would show).
TEST(GradientScale, TheDensityWalkTakesTheSameMoments) {
  for (const bool wendland : {false, true}) {
    testing::FluidBlock b(12, 10, 3, true, false);
    if (wendland) b.ctx.use_wendland_symmetric_gradient();
    jitter(b, 0.2);  // lists the pairs again and takes the densities
    const std::vector<double> density = b.p.density;
    compute_gradient_moment(b.ctx, b.list, b.p, true, b.work);
    const std::vector<double> moment = b.work.gradient_moment;
    b.work.gradient_moment.clear();
    for (double& rho : b.p.density) rho = 0.0;
    compute_summation_density_and_gradient_moment(b.ctx, b.list, b.p, true, b.work);
    double spread = 0.0;
    for (double m : moment) spread = std::max(spread, std::abs(m - 1.0));
    std::printf("%s: largest |m - 1| = %.3f\n", wendland ? "Wendland" : "cubic spline", spread);
    EXPECT_GT(spread, 1e-3);
    ASSERT_EQ(b.work.gradient_moment.size(), b.p.fluid_count);
    for (std::size_t i = 0; i < b.p.fluid_count; ++i) {
      EXPECT_EQ(b.p.density[i], density[i]) << "particle " << i;
      EXPECT_EQ(b.work.gradient_moment[i], moment[i]) << "particle " << i;
    }
  }
}

}  // namespace
}  // namespace washout
