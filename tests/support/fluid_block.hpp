#pragma once
// A 2D block of fluid particles on the lattice, neighbours listed and summation densities taken:
// the input of the unit tests of the PPE's terms and of the volume error near the surface.
#include "engine/core/neighbor_grid.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout::testing {

// nx x ny fluid particles of spacing kD0 from the origin, optionally on `floor_layers` rows of
// wall particles (normal +y, surface at y = 0) and periodic in x and/or y.
struct FluidBlock {
  static constexpr double kD0 = 0.01, kRho0 = 1000.0;
  SphContext ctx;
  Particles p;
  NeighborList list;
  FluidWork work;
  WallConditions walls;  // the floor: Neumann condition, free slip
  FluidBlock(int nx, int ny, int floor_layers, bool periodic_x, bool periodic_y)
      : ctx(2, kD0, 1.2, kRho0, box(nx, ny, periodic_x, periodic_y)) {
    p.dim = 2;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        p.add(ParticleKind::Fluid, Vec3((i + 0.5) * kD0, (j + 0.5) * kD0, 0), Vec3::Zero(), -1);
    for (int k = 0; k < floor_layers; ++k)
      for (int i = 0; i < nx; ++i)
        p.add(ParticleKind::FixedWall, Vec3((i + 0.5) * kD0, -(k + 0.5) * kD0, 0), Vec3::Zero(), 0,
              Vec3(0, 1, 0), (k + 0.5) * kD0);
    p.fluid_count = static_cast<std::size_t>(nx) * ny;
    NeighborGrid grid;
    grid.build(p, 2 * ctx.h, ctx.periodic);
    grid.build_list(p, p.size(), 2 * ctx.h, list);
    compute_summation_density(ctx, list, p);
    for (int a = 0; a < 3; ++a) work.u_star[a].assign(p.fluid_count, 0.0);
    walls.slip.assign(p.size() - p.fluid_count, 1.0);
  }
  static PeriodicBox box(int nx, int ny, bool px, bool py) {
    PeriodicBox b;
    b.periodic[0] = px, b.length[0] = nx * kD0;
    b.periodic[1] = py, b.length[1] = ny * kD0;
    return b;
  }
};

}  // namespace washout::testing
