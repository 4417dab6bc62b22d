// The source of the stabilized PPE (METHOD.md step 2, Asai et al. 2012):
//   b_i = (rho0/dt) <div u*>_i + alpha (rho0 - <rho>_i) / dt^2
// The divergence is the difference form over the fluid neighbours; the wall's share of it is
// what the Neumann condition imposes (ppe_wall_condition.cpp), except with dynamic walls, where
// the wall's own velocity enters the divergence.
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {
namespace {

// The dynamic wall's markers also hold the wall's clearance near the free surface, where the
// density-invariance term is off: a particle closer than 0.4 d0 to the nearest wall's surface
// meets that wall's markers coming back at half the shortfall per step, at most at the speed of
// a fall through one spacing, sqrt(|g| d0). (The lattice puts the first layer at d0/2; holding
// that exactly fed the noise of still water. The clearance undoes slow settling; a faster
// approach is an impact, which the mirrored markers stop. Uncapped, half the shortfall per step
// grows as 1/dt: particles squeezed to 0.2 d0 under the lifting gate of the 3D wash-out were
// pushed out at 2 m/s by pressures of 50-180 kPa; docs/method.md, twelfth session.)
// The mirrored velocity only stops an approach; without this the bottom particles of a thin
// flow on a no-slip floor settle towards it (to a fortieth of a spacing at a/20) and, where the
// flow hits a wall, are driven through the floor. The nearest wall particle gives the wall, and
// its face's markers (normals within 60 degrees of its own) push.
constexpr double kClearance = 0.4;  // [d0]: the lattice's d0/2 less a margin for its noise
constexpr double kClearanceRelaxation = 0.5;  // share of the shortfall closed in a step

struct WallClearance {
  std::size_t wall = std::numeric_limits<std::size_t>::max();  // nearest wall particle
  double speed = 0.0;                                          // marker's extra normal speed
};

WallClearance wall_clearance(const SphContext& ctx, const NeighborList& list, const Particles& p,
                             std::size_t i, double dt, double max_speed) {
  WallClearance c;
  const NearestBoundary nearest = nearest_boundary(ctx, list, p, i, /*skip_bodies=*/false);
  if (nearest.index == p.size()) return c;
  c.wall = nearest.index;
  // The distance to the nearest wall particle less its depth: exact straight above it, longer
  // beside it (so never a false alarm), and blind to the particle's normal, which beside a
  // corner can point along the diagonal.
  const double y = std::sqrt(nearest.r2) - p.wall_distance[c.wall];
  if (y < kClearance * ctx.d0)
    c.speed =
        std::min(max_speed, kClearanceRelaxation * (kClearance * ctx.d0 - std::max(y, 0.0)) / dt);
  return c;
}

}  // namespace

void subtract_ppe_source(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         const WallConditions& walls, const Vec3& gravity, double alpha, double dt,
                         const PpeRowFlags& flags, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  const double density_scale = alpha * ctx.rho0 / (dt * dt);
  // Without gravity nothing settles and nothing sets a speed: the clearance is uncapped.
  const double g = gravity.norm();
  const double clearance_speed =
      g > 0.0 ? std::sqrt(g * ctx.d0) : std::numeric_limits<double>::infinity();
  // Held since the previous step's move (empty in the first step, or with the option off).
  const bool strain = work.surface_strain.size() == n;
  // The density term's share alone, for density_kick = "positions" (density_kick.cpp).
  if (work.keep_density_rhs)
    work.density_rhs.assign(work.rhs.size(), 0.0);
  else
    work.density_rhs.clear();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    const double u_i[3] = {work.u_star[0][i], work.u_star[1][i], work.u_star[2][i]};
    // Near the surface, where the density-invariance term is off (below), nothing else holds
    // the wall's clearance; inside, that term does.
    const bool near_surface = flags.touches_surface[row] != 0;
    const WallClearance clearance = walls.dynamic && near_surface
                                        ? wall_clearance(ctx, list, p, i, dt, clearance_speed)
                                        : WallClearance{};
    const double div_u =
        divergence(ctx, list, p, i, u_i, [&](const NeighborPair& q, double u_j[3]) {
          const std::size_t j = q.j;
          // u_j is written in all three components (the divergence reads the first dim): with
          // constant bounds the writes stay in registers. Every array here holds three.
          if (j < n) {
            for (int a = 0; a < 3; ++a) u_j[a] = work.u_star[a][j];
          } else if (walls.dynamic) {
            // The wall's velocity plus the normal part of the virtual marker's velocity relative to
            // it (the fluid's, mirrored at the start of the step), with the same body-force
            // increment dt g as the fluid (the wall jump carries g - a_w). The tangential part is
            // left out: beyond the tip of a flow the markers are dry, and their tangential velocity
            // would read as a divergence.
            double marker_un = 0.0;
            for (int a = 0; a < ctx.dim; ++a)
              marker_un +=
                  (work.boundary.marker_velocity[a][j] - p.velocity[a][j]) * p.normal[a][j];
            // The wall's clearance (above): its face's markers come back at the shortfall.
            if (clearance.speed > 0.0) {
              double facing = 0.0;
              for (int a = 0; a < ctx.dim; ++a)
                facing += p.normal[a][j] * p.normal[a][clearance.wall];
              if (facing > 0.5) marker_un += clearance.speed;
            }
            for (int a = 0; a < 3; ++a)
              u_j[a] = p.velocity[a][j] + marker_un * p.normal[a][j] + dt * gravity[a];
          } else {
            for (int a = 0; a < 3; ++a) u_j[a] = u_i[a];  // no share of the divergence
          }
        });
    // Within a kernel support of the free surface the summation density is low only because the
    // support is truncated, not because the fluid expanded: the density-invariance term would
    // read that deficit as an error and pull the surface in. There the particle's accumulated
    // volumetric strain stands for the error (surface_strain.cpp; alpha_near_surface = "off":
    // no term), except on the surface itself, whose pressure the ghost condition sets.
    const double density_error = !near_surface ? (ctx.rho0 - p.density[i]) / ctx.rho0
                                 : strain && !work.free_surface[i] ? work.surface_strain[i]
                                                                   : 0.0;
    work.rhs[row] -= ctx.rho0 / dt * div_u + density_scale * density_error;
    if (work.keep_density_rhs) work.density_rhs[row] = -density_scale * density_error;
  }
}

}  // namespace washout
