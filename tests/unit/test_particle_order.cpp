// The fluid sorted by cell in memory (engine/core/particle_order.hpp): the order follows the
// cells with the longest axis slowest, depends on the state alone (not on the threads or on
// how the fluid was ordered before), moves every per-particle array together and leaves the
// boundary where it is; and the order of a list of ids puts a permuted fluid back.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "engine/core/particle_order.hpp"

namespace washout {
namespace {

// A block of nx x ny (x nz) fluid particles of spacing d, then a row of wall particles under it.
Particles block(int dim, int nx, int ny, int nz, double d) {
  Particles p;
  p.dim = dim;
  for (int k = 0; k < (dim == 3 ? nz : 1); ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        p.add(ParticleKind::Fluid, Vec3((i + 0.5) * d, (j + 0.5) * d, (k + 0.5) * d), Vec3(i, j, k),
              /*group_index=*/j % 3);
  for (int i = 0; i < nx; ++i)
    p.add(ParticleKind::FixedWall, Vec3((i + 0.5) * d, -0.5 * d, 0.5 * d), Vec3::Zero(), 7,
          Vec3(0, 1, 0), 0.5 * d);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.pressure[i] = 1000.0 + i;
    p.density[i] = 990.0 + 0.1 * i;
  }
  return p;
}

FluidOrder random_order(std::size_t n, unsigned seed) {
  FluidOrder order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::mt19937 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  return order;
}

long cell(double x, double size) { return static_cast<long>(std::floor(x / size)); }

TEST(ParticleOrder, ByCellsWithTheLongestAxisSlowest) {
  const double d = 0.01, cell_size = 0.012;
  // 2D: x the long axis; 3D: z the long axis, then x, then y.
  struct Case {
    int dim, nx, ny, nz, axes[3];
  };
  for (const Case c : {Case{2, 40, 8, 1, {0, 1, 2}}, Case{3, 10, 6, 24, {2, 0, 1}}}) {
    Particles p = block(c.dim, c.nx, c.ny, c.nz, d);
    permute_fluid(p, random_order(p.fluid_count, 3));
    const FluidOrder order = fluid_cell_order(p, cell_size);
    permute_fluid(p, order);
    long disorders = 0;
    for (std::size_t k = 1; k < p.fluid_count; ++k) {
      // The cells of k - 1 and k, compared axis by axis from the slowest.
      for (int s = 0; s < c.dim; ++s) {
        const int a = c.axes[s];
        const long before = cell(p.position[a][k - 1] - 0.5 * d, cell_size);
        const long now = cell(p.position[a][k] - 0.5 * d, cell_size);
        if (now == before) continue;
        disorders += now < before;
        break;
      }
    }
    EXPECT_EQ(disorders, 0) << c.dim << "D";
    // Within a cell, by the index held before: the wall rows never move.
    EXPECT_EQ(p.kind[p.fluid_count], static_cast<std::uint8_t>(ParticleKind::FixedWall));
  }
}

TEST(ParticleOrder, DependsOnTheStateAloneNotOnTheThreads) {
  Particles p = block(3, 12, 5, 7, 0.01);
  permute_fluid(p, random_order(p.fluid_count, 11));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const FluidOrder one = fluid_cell_order(p, 0.012);
  omp_set_num_threads(2);
  const FluidOrder two = fluid_cell_order(p, 0.012);
  omp_set_num_threads(threads);
  EXPECT_EQ(one, two);
  // Sorting a sorted fluid again changes nothing.
  permute_fluid(p, one);
  EXPECT_TRUE(is_identity(fluid_cell_order(p, 0.012)));
}

TEST(ParticleOrder, RetiredParticlesGoLast) {
  Particles p = block(2, 10, 4, 1, 0.01);
  for (std::size_t i : {3u, 17u, 25u}) p.kind[i] = static_cast<std::uint8_t>(ParticleKind::Retired);
  const FluidOrder order = fluid_cell_order(p, 0.012);
  const std::size_t n = p.fluid_count;
  EXPECT_EQ(std::vector<std::uint32_t>(order.end() - 3, order.end()),
            (std::vector<std::uint32_t>{3, 17, 25}));
  for (std::size_t k = 0; k + 3 < n; ++k)
    EXPECT_EQ(p.kind[order[k]], static_cast<std::uint8_t>(ParticleKind::Fluid));
}

TEST(ParticleOrder, EveryArrayMovesTogetherAndTheBoundaryStays) {
  const Particles built = block(3, 6, 5, 4, 0.01);
  Particles p = built;
  const FluidOrder order = random_order(p.fluid_count, 5);
  permute_fluid(p, order);
  for (std::size_t k = 0; k < p.fluid_count; ++k) {
    const std::size_t was = order[k];
    EXPECT_EQ(p.id[k], was);
    EXPECT_EQ(p.x(k), built.x(was));
    EXPECT_EQ(p.u(k), built.u(was));
    EXPECT_EQ(p.pressure[k], built.pressure[was]);
    EXPECT_EQ(p.density[k], built.density[was]);
    EXPECT_EQ(p.group[k], built.group[was]);
  }
  for (std::size_t i = p.fluid_count; i < p.size(); ++i) {
    EXPECT_EQ(p.id[i], i);
    EXPECT_EQ(p.x(i), built.x(i));
    EXPECT_EQ(p.normal[1][i], 1.0);
    EXPECT_EQ(p.group[i], 7);
  }
  // inverse_order undoes it: new_index[old] = k.
  const auto new_index = inverse_order(order);
  for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(new_index[order[k]], k);
}

TEST(ParticleOrder, TheOrderOfIdsPutsAPermutedFluidBack) {
  const Particles built = block(2, 9, 7, 1, 0.01);
  Particles p = built;
  permute_fluid(p, random_order(p.fluid_count, 8));
  permute_fluid(p, random_order(p.fluid_count, 9));
  std::vector<std::uint64_t> ids(p.fluid_count);
  std::iota(ids.begin(), ids.end(), std::uint64_t{0});
  permute_fluid(p, order_of_ids(p, ids));
  for (int a = 0; a < 3; ++a) EXPECT_EQ(p.position[a], built.position[a]);
  EXPECT_EQ(p.id, built.id);
  EXPECT_EQ(p.pressure, built.pressure);
  // Anything but a permutation of the fluid's ids is refused.
  ids[5] = ids[6];
  EXPECT_THROW(order_of_ids(p, ids), std::invalid_argument);
  ids.pop_back();
  EXPECT_THROW(order_of_ids(p, ids), std::invalid_argument);
}

}  // namespace
}  // namespace washout
