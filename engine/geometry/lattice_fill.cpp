#include "engine/geometry/lattice_fill.hpp"

#include <cmath>

namespace washout {

std::vector<Vec3> lattice_points_inside(const Shape& shape, int dim, double d0, double max_depth) {
  std::vector<Vec3> points;
  if (shape.empty()) return points;
  const Aabb b = shape.bounds(dim);
  long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int a = 0; a < dim; ++a) {
    lo[a] = static_cast<long>(std::floor(b.lower[a] / d0 - 0.5)) - 1;
    hi[a] = static_cast<long>(std::ceil(b.upper[a] / d0 - 0.5)) + 1;
  }
  // Half a spacing of tolerance keeps points that sit exactly on a lattice-aligned face out.
  const double eps = 1e-9 * d0;
  for (long k = lo[2]; k <= hi[2]; ++k)
    for (long j = lo[1]; j <= hi[1]; ++j)
      for (long i = lo[0]; i <= hi[0]; ++i) {
        const Vec3 p((i + 0.5) * d0, (j + 0.5) * d0, dim == 3 ? (k + 0.5) * d0 : 0.0);
        const double s = shape.signed_distance(p, dim);
        if (s < -eps && -s <= max_depth + eps) points.push_back(p);
      }
  return points;
}

}  // namespace washout
