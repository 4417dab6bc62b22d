#include "engine/boundary/virtual_markers.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/fluid_interpolation.hpp"
#include "engine/core/shared_mark.hpp"

namespace washout {

std::size_t mark_active_boundary(const NeighborList& list, const Particles& p,
                                 std::vector<std::uint8_t>& active) {
  active.assign(p.size(), 0);
  // One pass over every fluid pair: on all threads (serial it was about 1 % of a step); threads
  // that meet the same wall particle all mark it.
  const std::size_t queries = list.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < queries; ++i)
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::uint32_t j = list.index[k];
      if (j < p.fluid_count) continue;
      mark_shared(active[j]);
    }
  std::size_t count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (std::size_t w = p.fluid_count; w < p.size(); ++w) count += active[w];
  return count;
}

void mark_boundary_near_fluid(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                              std::vector<std::uint8_t>& active) {
  active.assign(p.size(), 0);
  const double r2max = 4.0 * ctx.h * ctx.h;
  const std::size_t fluid = p.fluid_count;
  // Walked from the fluid: the walls outnumber it (7 to 1 in the 3D dam break) and most of them
  // are dry, each a walk of 125 cells that found nothing (2 % of the a/20 run, at the frames
  // alone). The distance is the wall's to the fluid, as a walk from the wall takes it.
#pragma omp parallel for schedule(static)
  for (std::size_t f = 0; f < fluid; ++f) {
    if (p.retired(f)) continue;  // in no cell: no wall finds it
    const double x[3] = {p.position[0][f], p.position[1][f], p.position[2][f]};
    grid.for_each_candidate(x, [&](std::uint32_t w) {
      if (w < fluid) return;
      double d[3];
      ctx.displacement(p, w, f, d);
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < r2max) mark_shared(active[w]);
    });
  }
}

void update_marker_velocities(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                              const std::vector<std::uint8_t>& active, const WallConditions& walls,
                              BoundaryWork& work) {
  const std::size_t n = p.size();
  for (int a = 0; a < 3; ++a) work.marker_velocity[a].resize(n, 0.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t w = p.fluid_count; w < n; ++w) {
    if (!active[w]) continue;
    double m[3], normal[3], u_wall[3];
    for (int a = 0; a < 3; ++a) {
      normal[a] = p.normal[a][w];
      u_wall[a] = p.velocity[a][w];
      m[a] = p.position[a][w] + 2.0 * p.wall_distance[w] * normal[a];
    }
    double u_m[3] = {0, 0, 0};
    const double fraction =
        interpolate_fluid_linear(ctx, grid, p, m, [&](std::uint32_t f, double wt) {
          for (int a = 0; a < ctx.dim; ++a) u_m[a] += wt * p.velocity[a][f];
        });
    if (fraction < kDryFluidFraction) {
      for (int a = 0; a < 3; ++a) work.marker_velocity[a][w] = u_wall[a];
      continue;
    }
    double rel[3], un = 0.0;
    for (int a = 0; a < 3; ++a) {
      rel[a] = u_m[a] - u_wall[a];
      un += rel[a] * normal[a];
    }
    const double tangential_factor = 2.0 * walls.slip[w - p.fluid_count] - 1.0;
    // Fluid coming at the wall (un < 0) meets a marker coming back at it, so that the
    // wall's share of the divergence stops it. Fluid leaving the wall faster than the
    // separation speed U meets a marker leaving with it: a wall pushes but does not pull, and
    // the fluid may separate (below U, the blend keeps still water symmetric about the wall).
    const double leaving =
        un > 0.0 && walls.separation_speed > 0.0 ? std::min(1.0, un / walls.separation_speed) : 0.0;
    const double marker_un = -un + 2.0 * leaving * un;
    for (int a = 0; a < 3; ++a) {
      const double tangential_part = rel[a] - un * normal[a];
      work.marker_velocity[a][w] =
          u_wall[a] + marker_un * normal[a] + tangential_factor * tangential_part;
    }
  }
}

void update_wall_pressures(const SphContext& ctx, const NeighborGrid& grid, const Vec3& gravity,
                           const std::vector<std::uint8_t>& active, Particles& p) {
  const std::size_t n = p.size();
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t w = p.fluid_count; w < n; ++w) {
    if (!active[w]) {
      p.pressure[w] = 0.0;
      continue;
    }
    double m[3];
    for (int a = 0; a < 3; ++a) m[a] = p.position[a][w] + 2.0 * p.wall_distance[w] * p.normal[a][w];
    double P_m = 0.0;
    const double fraction = interpolate_fluid_linear(
        ctx, grid, p, m, [&](std::uint32_t f, double wt) { P_m += wt * p.pressure[f]; });
    if (fraction < kDryFluidFraction) {
      p.pressure[w] = 0.0;
      continue;
    }
    double hydrostatic = 0.0;
    for (int a = 0; a < ctx.dim; ++a) hydrostatic += gravity[a] * (p.position[a][w] - m[a]);
    p.pressure[w] = P_m + ctx.rho0 * hydrostatic;
  }
}

}  // namespace washout
