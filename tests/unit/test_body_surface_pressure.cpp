// The pressure on a body's surface as a linear map (engine/sim/body_surface_pressure.hpp,
// SurfaceStencil): the body coupling evaluates the load of six response fields and of each
// correction of the pressure every step, and searches the fluid around the surface once for all
// of them. The map must give what the interpolation gives for the same field: the same bits where
// the surface is under water (no clamp there), zero where it is dry, and nothing from fluid
// that is no unknown of the PPE.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/core/neighbor_grid.hpp"
#include "engine/sim/body_surface_pressure.hpp"

namespace washout {
namespace {

constexpr double kD0 = 0.01;

double field(const Vec3& x) { return 1000.0 + 3e4 * x[0] - 7e4 * x[1] + 2e5 * x[0] * x[1]; }

// A 2D pool 20 x 8 spacings over a floor whose top face is y = 0; the floor's particles are the
// "body" surface, half of them under the pool and half beyond its end (dry).
struct Pool {
  Particles p;
  std::vector<std::uint32_t> surface;
  std::vector<std::int32_t> unknown;
};

Pool make_pool(bool every_fluid_particle_an_unknown) {
  Pool pool;
  Particles& p = pool.p;
  p.dim = 2;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 20; ++i)
      p.add(ParticleKind::Fluid, Vec3((i + 0.5) * kD0, (j + 0.5) * kD0, 0.0), Vec3::Zero(), -1);
  p.fluid_count = p.size();
  for (std::size_t f = 0; f < p.fluid_count; ++f) {
    p.pressure[f] = field(p.x(f));
    const bool surface_row = p.position[1][f] > 7.0 * kD0;
    pool.unknown.push_back(every_fluid_particle_an_unknown || !surface_row ? std::int32_t(f) : -1);
  }
  for (int i = 2; i < 36; ++i) {
    pool.surface.push_back(static_cast<std::uint32_t>(p.size()));
    p.add(ParticleKind::RigidBody, Vec3((i + 0.5) * kD0, -0.5 * kD0, 0.0), Vec3::Zero(), -1,
          Vec3(0.0, 1.0, 0.0), 0.5 * kD0);
  }
  return pool;
}

TEST(BodySurfacePressure, StencilGivesTheInterpolatedPressure) {
  Pool pool = make_pool(true);
  const Particles& p = pool.p;
  const SphContext ctx(2, kD0, 1.2, 1000.0, PeriodicBox{});
  NeighborGrid grid;
  grid.build(p, 2.0 * ctx.h, PeriodicBox{});
  std::vector<double> interpolated, mapped;
  body_surface_pressure(ctx, grid, p, Vec3::Zero(), pool.surface, interpolated);
  SurfaceStencil stencil;
  build_surface_stencil(ctx, grid, p, pool.surface, pool.unknown, stencil);
  std::vector<double> rows(p.pressure.begin(), p.pressure.begin() + p.fluid_count);
  stencil_pressure(ctx, stencil, rows, mapped);
  ASSERT_EQ(mapped.size(), pool.surface.size());
  int wet = 0, dry = 0;
  for (std::size_t k = 0; k < mapped.size(); ++k) {
    EXPECT_EQ(mapped[k], interpolated[k]) << "surface point " << k;
    if (stencil.fraction[k] > 0.0) {
      ++wet;
    } else {
      ++dry;
      EXPECT_EQ(mapped[k], 0.0);
    }
  }
  std::printf("%d wet and %d dry surface points, the same bits as the interpolation\n", wet, dry);
  EXPECT_GT(wet, 10);
  EXPECT_GT(dry, 10);
}

// Fluid that is no unknown (the free-surface row here) takes no part: the map of a field equals
// the interpolation of that field with those particles' values set to zero.
TEST(BodySurfacePressure, StencilLeavesOutFluidThatIsNoUnknown) {
  Pool pool = make_pool(false);
  Particles& p = pool.p;
  const SphContext ctx(2, kD0, 1.2, 1000.0, PeriodicBox{});
  NeighborGrid grid;
  grid.build(p, 2.0 * ctx.h, PeriodicBox{});
  SurfaceStencil stencil;
  build_surface_stencil(ctx, grid, p, pool.surface, pool.unknown, stencil);
  std::vector<double> rows(p.fluid_count, 0.0), mapped, interpolated;
  for (std::size_t f = 0; f < p.fluid_count; ++f)
    if (pool.unknown[f] >= 0)
      rows[pool.unknown[f]] = p.pressure[f];
    else
      p.pressure[f] = 0.0;
  stencil_pressure(ctx, stencil, rows, mapped);
  body_surface_pressure(ctx, grid, p, Vec3::Zero(), pool.surface, interpolated);
  for (std::size_t k = 0; k < mapped.size(); ++k)
    EXPECT_DOUBLE_EQ(mapped[k], interpolated[k]) << "surface point " << k;
}

// A body short of the fluid (the girder before the wave) skips the searches when its box and the
// fluid's are apart by more than the reach (beyond_fluid_reach). Never wrongly: a box of body
// particles placed at gaps from 0.5 to 6 spacings beyond the pool's end, turned, says it is out
// of reach only where no fluid particle is within 2h of a particle or of its mirror point and
// the interpolated surface pressure is zero at every point; and it says so for the far gaps.
TEST(BodySurfacePressure, OutOfReachOnlyWhereNoSearchWouldFindFluid) {
  Pool pool = make_pool(true);
  Particles& p = pool.p;
  const SphContext ctx(2, kD0, 1.2, 1000.0, PeriodicBox{});
  const double reach2 = 4.0 * ctx.h * ctx.h;
  int out_of_reach = 0, in_reach = 0;
  for (double gap = 0.5; gap <= 6.0; gap += 0.25) {
    for (double angle : {0.0, 0.3, 1.1}) {
      Particles q = p;
      const std::size_t first = q.size();
      // A 4 x 3 block of body particles, its nearest corner `gap` spacings beyond the pool's end
      // (x = 20 d0) at mid-depth, each at half a spacing from the body's surface.
      const Vec3 corner(20.0 * kD0 + gap * kD0, 4.0 * kD0, 0.0);
      const Vec3 along(std::cos(angle), std::sin(angle), 0.0), up(-along.y(), along.x(), 0.0);
      std::vector<std::uint32_t> body;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
          body.push_back(static_cast<std::uint32_t>(q.size()));
          q.add(ParticleKind::RigidBody, corner + (i * along + j * up) * kD0, Vec3::Zero(), -1,
                j == 0 ? Vec3(-up) : Vec3(up), 0.5 * kD0);
        }
      const bool out = beyond_fluid_reach(ctx, q, fluid_box(q), first, body.size());
      bool found = false;
      for (std::uint32_t w : body)
        for (std::size_t f = 0; f < q.fluid_count; ++f)
          for (const Vec3& x :
               {Vec3(q.x(w)), Vec3(q.x(w) + 2.0 * q.wall_distance[w] *
                                                Vec3(q.normal[0][w], q.normal[1][w], 0.0))})
            found = found || (x - q.x(f)).squaredNorm() < reach2;
      NeighborGrid grid;
      grid.build(q, 2.0 * ctx.h, PeriodicBox{});
      std::vector<double> pressure;
      body_surface_pressure(ctx, grid, q, Vec3::Zero(), body, pressure);
      if (out) {
        ++out_of_reach;
        EXPECT_FALSE(found) << "gap " << gap << ", angle " << angle;
        for (double value : pressure) EXPECT_EQ(value, 0.0) << "gap " << gap;
      } else {
        ++in_reach;
      }
      if (gap >= 5.0) {
        EXPECT_TRUE(out) << "gap " << gap << ", angle " << angle;
      }
    }
  }
  std::printf("%d placements out of reach (no search needed), %d in reach\n", out_of_reach,
              in_reach);
  EXPECT_GT(in_reach, 10);
}

}  // namespace
}  // namespace washout
