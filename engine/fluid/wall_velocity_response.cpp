#include "engine/fluid/wall_velocity_response.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "engine/core/shared_mark.hpp"

namespace washout {

void assemble_wall_velocity_response(const SphContext& ctx, const NeighborList& list,
                                     const Particles& p, const FluidWork& work,
                                     std::span<const int> first_column,
                                     std::span<const Vec3> centre, double dt,
                                     std::span<const std::uint32_t> rows,
                                     std::vector<std::vector<double>>& columns) {
  const std::size_t n = p.fluid_count;
  for (auto& c : columns) c.assign(work.matrix.rows, 0.0);
  const double scale = ctx.rho0 / dt;
  const bool planar = ctx.dim == 2;
#pragma omp parallel for schedule(dynamic, 64)
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::size_t i = rows[r];
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t w = list.index[k];
      if (w < n) continue;
      const std::int32_t b = p.body[w];
      if (b < 0 || first_column[b] < 0) continue;
      double d[3];
      ctx.displacement(p, i, w, d);
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double r = std::sqrt(r2);
      const double c = -ctx.laplacian_weight(r, r2);  // c_iw of the assembly
      // d rhs_i / d u_w = (rho0/dt) c_iw n_w (n_w . d_iw)
      const Vec3 normal(p.normal[0][w], p.normal[1][w], p.normal[2][w]);
      const double dn = normal.dot(Vec3(d[0], d[1], d[2]));
      if (dn <= 0.0) continue;  // i behind w's face: the jump has no acceleration term
      const Vec3 v = scale * c * dn * normal;
      const Vec3 arm = p.x(w) - centre[b];
      const Vec3 moment = arm.cross(v);  // v . (w x arm) = w . (arm x v)
      const int first = first_column[b];
      for (int a = 0; a < ctx.dim; ++a) columns[first + a][row] += v[a];
      if (planar)
        columns[first + 2][row] += moment.z();
      else
        for (int a = 0; a < 3; ++a) columns[first + 3 + a][row] += moment[a];
    }
  }
}

void fluid_beside_bodies(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                         std::span<const int> first_column, std::vector<std::uint8_t>& mark,
                         std::vector<std::uint32_t>& rows) {
  const std::size_t n = p.fluid_count;
  const double r2max = 4.0 * ctx.h * ctx.h;
  mark.assign(n, 0);
  rows.clear();  // first the bodies' particles, then the rows
  for (std::size_t w = n; w < p.size(); ++w) {
    const std::int32_t b = p.body[w];
    if (b >= 0 && first_column[b] >= 0) rows.push_back(static_cast<std::uint32_t>(w));
  }
  // The searches around them on all threads (serial they were 0.5 s of the README wash-out);
  // threads may find the same fluid particle.
  const std::size_t count = rows.size();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t w = rows[k];
    const double x[3] = {p.position[0][w], p.position[1][w], p.position[2][w]};
    thread_local std::vector<std::uint32_t> found;
    const std::size_t near = grid.collect_below(p, x, static_cast<std::uint32_t>(n), r2max, found);
    for (std::size_t m = 0; m < near; ++m) mark_shared(mark[found[m]]);
  }
  rows.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (mark[i]) rows.push_back(static_cast<std::uint32_t>(i));
}

}  // namespace washout
