#include "engine/sim/probes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/cubic_spline_kernel.hpp"
#include "engine/core/fluid_interpolation.hpp"

namespace washout {
namespace {

bool is_fluid(const Particles& p, std::size_t i) {
  return p.kind[i] == static_cast<std::uint8_t>(ParticleKind::Fluid);
}

// Particle i's offset from the gauge's vertical line through `point` (the `up` component zero),
// across periodic boundaries the shortest.
void offset_across(const SphContext& ctx, const Particles& p, std::size_t i, int up,
                   const Vec3& point, double d[3]) {
  for (int a = 0; a < 3; ++a) d[a] = a < p.dim && a != up ? p.position[a][i] - point[a] : 0.0;
  if (ctx.periodic.any()) ctx.periodic.minimum_image(d);
}

}  // namespace

double sensor_pressure(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                       const ProbeSpec& probe) {
  const double m[3] = {probe.point[0], probe.point[1], probe.point[2]};
  const bool one_side = probe.facing.squaredNorm() > 0.0;
  double sum = 0.0, weight = 0.0;
  // The grid was built at the start of the step; particles moved by at most cfl*h since.
  accumulate_fluid_at(ctx, grid, p, m, [&](std::uint32_t f, double w) {
    if (one_side) {
      // Across a periodic seam the side is the minimum image's, as the weight's distance is.
      double d[3] = {p.position[0][f] - m[0], p.position[1][f] - m[1], p.position[2][f] - m[2]};
      if (ctx.periodic.any()) ctx.periodic.minimum_image(d);
      double ahead = 0.0;
      for (int a = 0; a < p.dim; ++a) ahead += d[a] * probe.facing[a];
      if (ahead < 0.0) return;
    }
    sum += w * p.pressure[f];
    weight += w;
  });
  const double fraction = weight * ctx.volume;
  return fraction < kDryFluidFraction ? 0.0 : sum * ctx.volume / fraction;
}

namespace {

double surface_height(const SphContext& ctx, const Particles& p, int up, const Vec3& point) {
  const std::size_t n = p.fluid_count;
  std::vector<double> column;
#pragma omp parallel
  {
    std::vector<double> mine;
#pragma omp for nowait
    for (std::size_t i = 0; i < n; ++i) {
      if (!is_fluid(p, i)) continue;
      double d[3];
      offset_across(ctx, p, i, up, point, d);
      if (std::abs(d[0]) <= ctx.d0 && std::abs(d[1]) <= ctx.d0 && std::abs(d[2]) <= ctx.d0)
        mine.push_back(p.position[up][i]);
    }
#pragma omp critical(gauge_column)
    column.insert(column.end(), mine.begin(), mine.end());
  }
  std::sort(column.begin(), column.end());
  // Up from the bed while the next particle is within the air gap of the water below it.
  const double bed = point[up];
  const double gap = kGaugeAirGap * ctx.d0;
  double reach = bed;
  double top = -std::numeric_limits<double>::max();
  for (double z : column) {
    if (z > reach + gap) break;
    top = std::max(top, z);
    reach = std::max(reach, z);
  }
  return std::max(0.0, top + 0.5 * ctx.d0 - bed);
}

double wetted_length(const SphContext& ctx, const Particles& p, int up, const Vec3& point) {
  const std::size_t n = p.fluid_count;
  const CubicSplineKernel across(p.dim - 1, ctx.h);
  const double r2max = 4.0 * ctx.h * ctx.h;
  double length = 0.0;
#pragma omp parallel for reduction(+ : length)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_fluid(p, i) || p.position[up][i] < point[up]) continue;
    double d[3];
    offset_across(ctx, p, i, up, point, d);
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (r2 < r2max) length += across.value(std::sqrt(r2));
  }
  return length * ctx.volume;
}

}  // namespace

double water_height(const SphContext& ctx, const Particles& p, int up, const ProbeSpec& probe) {
  return probe.gauge == ProbeSpec::Gauge::Surface ? surface_height(ctx, p, up, probe.point)
                                                  : wetted_length(ctx, p, up, probe.point);
}

double front_position(const SphContext& ctx, const Particles& p, double rho0,
                      const ProbeSpec& probe) {
  const std::size_t n = p.fluid_count;
  double front = -std::numeric_limits<double>::max();
#pragma omp parallel for reduction(max : front)
  for (std::size_t i = 0; i < n; ++i)
    if (p.density[i] > 0.5 * rho0 && is_fluid(p, i))
      front = std::max(front, p.position[probe.axis][i]);
  return front + 0.5 * ctx.d0;
}

}  // namespace washout
