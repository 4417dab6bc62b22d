#include "engine/boundary/wall_acceleration.hpp"

#include <algorithm>

namespace washout {

void update_wall_accelerations(const Particles& p, const std::vector<std::uint8_t>& solved_body,
                               double dt, std::array<std::vector<double>, 3>& previous,
                               BoundaryWork& work) {
  const std::size_t n = p.size(), first = p.fluid_count;
  for (int a = 0; a < 3; ++a) {
    work.wall_acceleration[a].resize(n);
    std::fill(work.wall_acceleration[a].begin(), work.wall_acceleration[a].begin() + first, 0.0);
    if (previous[a].size() != n) previous[a].assign(p.velocity[a].begin(), p.velocity[a].end());
  }
  // Every wall particle, wet or dry (a dry one's velocity history is needed when it wets): on
  // all threads, as the other stages (serial, this loop over 55,000 walls was 1 % of the 3D
  // dam break at a/20 and did not scale).
#pragma omp parallel for schedule(static)
  for (std::size_t w = first; w < n; ++w) {
    const std::int32_t b = p.body[w];
    const bool solved =
        b >= 0 && static_cast<std::size_t>(b) < solved_body.size() && solved_body[b];
    double acc[3], an = 0.0;
    for (int a = 0; a < 3; ++a) {
      acc[a] = solved ? 0.0 : (p.velocity[a][w] - previous[a][w]) / dt;
      previous[a][w] = p.velocity[a][w];
      an += acc[a] * p.normal[a][w];
    }
    if (an < 0.0)
      for (int a = 0; a < 3; ++a) acc[a] -= an * p.normal[a][w];
    for (int a = 0; a < 3; ++a) work.wall_acceleration[a][w] = acc[a];
  }
}

}  // namespace washout
