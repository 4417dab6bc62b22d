#include "engine/boundary/squeeze_film.hpp"

#include <cmath>

namespace washout {
namespace {

// A solid a boundary particle belongs to: bodies and walls numbered apart.
std::int64_t solid_of(const Particles& p, std::size_t w) {
  return p.body[w] >= 0 ? -1 - static_cast<std::int64_t>(p.body[w]) : p.group[w];
}

}  // namespace

std::size_t mark_squeeze_film(const SphContext& ctx, const NeighborList& list, const Particles& p,
                              BoundaryWork& work) {
  const std::size_t n = p.fluid_count;
  work.film.assign(n, 0);
  // Faces at more than 120 degrees. This takes in the open water beside a box's bottom
  // corner on the floor (its corner particle's diagonal normal meets the floor's at 135
  // degrees), where the film's flow leaves the gap: with 155 degrees instead, the particles
  // there stayed in the PPE and were thrown out at 26 m/s as the box landed (d0 = 0.005 m).
  constexpr double kFacing = -0.5;
  constexpr double kSameFace = 0.9;  // one face of a solid: normals within about 25 degrees
  std::size_t count = 0;
#pragma omp parallel for reduction(+ : count) schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    // The nearby faces (solid, orientation) seen so far; a particle rarely sees more than three.
    constexpr int kMaxFaces = 8;
    std::int64_t solid[kMaxFaces];
    double normal[kMaxFaces][3];
    bool body[kMaxFaces];
    int faces = 0;
    bool film = false;
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1] && !film; ++k) {
      const std::size_t w = list.index[k];
      if (w < n) continue;
      double d[3];
      ctx.displacement(p, i, w, d);
      // Distance from i to w's face, along the face's normal (i in front of it when positive).
      double along = 0.0;
      for (int a = 0; a < ctx.dim; ++a) along += d[a] * p.normal[a][w];
      const double gap = along - p.wall_distance[w];
      if (along <= 0.0 || gap >= ctx.d0) continue;
      const std::int64_t s = solid_of(p, w);
      bool known = false;  // a face of this solid with the same orientation is recorded
      for (int f = 0; f < faces && !film; ++f) {
        double cosine = 0.0;
        for (int a = 0; a < ctx.dim; ++a) cosine += normal[f][a] * p.normal[a][w];
        if (solid[f] == s)
          known = known || cosine > kSameFace;
        else
          film = (body[f] || p.body[w] >= 0) && cosine < kFacing;
      }
      if (!known && faces < kMaxFaces) {
        solid[faces] = s;
        body[faces] = p.body[w] >= 0;
        for (int a = 0; a < 3; ++a) normal[faces][a] = p.normal[a][w];
        ++faces;
      }
    }
    work.film[i] = film;
    count += film;
  }
  return count;
}

void set_film_pressure(const SphContext& ctx, const NeighborList& list, const Particles& p,
                       const Vec3& gravity, const std::vector<std::uint8_t>& free_surface,
                       BoundaryWork& work) {
  const std::size_t n = p.fluid_count;
  work.film_pressure.assign(n, 0.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (!work.film[i]) continue;
    double sum = 0.0;
    int count = 0;
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t j = list.index[k];
      if (j >= n || work.film[j] || free_surface[j]) continue;
      double d[3];
      ctx.displacement(p, i, j, d);
      double hydrostatic = 0.0;
      for (int a = 0; a < ctx.dim; ++a) hydrostatic += gravity[a] * d[a];
      sum += p.pressure[j] + ctx.rho0 * hydrostatic;
      ++count;
    }
    work.film_pressure[i] = count > 0 ? sum / count : 0.0;
  }
}

}  // namespace washout
