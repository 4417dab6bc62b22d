// Which boundary particles see fluid (virtual_markers.hpp): the step marks them from its
// neighbour lists (mark_active_boundary), a frame from a grid built on the positions the step
// left (mark_boundary_near_fluid, walked from the fluid). Both must give exactly the boundary
// particles closer than 2h to some fluid particle that takes part: the frame's wall pressures
// are fitted on those alone, and a mark missed leaves a wet wall at zero pressure.
#include <gtest/gtest.h>

#include <random>

#include "engine/boundary/virtual_markers.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"

namespace washout {
namespace {

// Fluid scattered in the unit box's middle, boundary particles over the whole box and beyond it,
// so that some see fluid and most do not (as the walls of a dam break).
Particles fluid_and_walls(int dim, std::size_t fluid, std::size_t walls, unsigned seed) {
  Particles p;
  p.dim = dim;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> inner(0.3, 0.7), outer(-0.2, 1.2);
  for (std::size_t i = 0; i < fluid; ++i)
    p.add(ParticleKind::Fluid, Vec3(inner(rng), inner(rng), dim == 3 ? inner(rng) : 0.0),
          Vec3::Zero(), -1);
  for (std::size_t i = 0; i < walls; ++i)
    p.add(ParticleKind::FixedWall, Vec3(outer(rng), outer(rng), dim == 3 ? outer(rng) : 0.0),
          Vec3::Zero(), 0);
  return p;
}

// The brute-force answer: a boundary particle is marked when a fluid particle that takes part
// (not retired) is closer than 2h, minimum image along periodic axes.
std::vector<std::uint8_t> marked_by_brute_force(const SphContext& ctx, const Particles& p) {
  std::vector<std::uint8_t> marked(p.size(), 0);
  const double r2max = 4.0 * ctx.h * ctx.h;
  for (std::size_t w = p.fluid_count; w < p.size(); ++w)
    for (std::size_t f = 0; f < p.fluid_count && !marked[w]; ++f) {
      if (p.retired(f)) continue;
      double d[3];
      ctx.displacement(p, w, f, d);
      marked[w] = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < r2max;
    }
  return marked;
}

TEST(ActiveBoundary, TheFrameAndTheStepMarkTheWallsWithinReachOfTheFluid) {
  for (int dim : {2, 3})
    for (bool periodic : {false, true}) {
      PeriodicBox box;
      if (periodic) box.periodic[0] = true, box.lower[0] = -0.2, box.length[0] = 1.4;
      const SphContext ctx(dim, 0.02, 1.2, 1000.0, box);  // 2h = 0.048
      Particles p = fluid_and_walls(dim, dim == 2 ? 400 : 1500, dim == 2 ? 3000 : 12000, 5);
      if (periodic)  // fluid across the periodic seam: walls beyond it see it through the image
        for (std::size_t f = 0; f < 40; ++f) p.position[0][f] = 1.19 - 0.001 * f;
      for (std::size_t f = 0; f < p.fluid_count; f += 9)  // left the domain: sees nobody
        p.kind[f] = static_cast<std::uint8_t>(ParticleKind::Retired);

      NeighborGrid grid;
      grid.build(p, 2.0 * ctx.h, box);
      NeighborList list;
      grid.build_list(p, p.fluid_count, 2.0 * ctx.h, list);
      std::vector<std::uint8_t> from_lists, from_grid;
      const std::size_t listed = mark_active_boundary(list, p, from_lists);
      mark_boundary_near_fluid(ctx, grid, p, from_grid);
      const std::vector<std::uint8_t> expected = marked_by_brute_force(ctx, p);

      std::size_t wrong_lists = 0, wrong_grid = 0, wet = 0;
      for (std::size_t w = p.fluid_count; w < p.size(); ++w) {
        wet += expected[w];
        wrong_lists += from_lists[w] != expected[w];
        wrong_grid += from_grid[w] != expected[w];
      }
      for (std::size_t f = 0; f < p.fluid_count; ++f) wrong_grid += from_grid[f] != 0;
      std::printf(
          "dim %d, periodic %d: %zu of %zu boundary particles see fluid; %zu (lists), %zu "
          "(grid) marked wrong\n",
          dim, periodic, wet, p.size() - p.fluid_count, wrong_lists, wrong_grid);
      EXPECT_EQ(wrong_lists, 0u);
      EXPECT_EQ(wrong_grid, 0u);
      EXPECT_EQ(listed, wet);
      EXPECT_GT(wet, 100u);                            // the test sees wet walls
      EXPECT_LT(wet, (p.size() - p.fluid_count) / 2);  // and dry ones
    }
}

}  // namespace
}  // namespace washout
