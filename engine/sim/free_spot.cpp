#include "engine/sim/free_spot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace washout {

std::optional<Vec3> find_free_spot(const Vec3& x, int dim, double d0, int max_rings,
                                   const std::function<bool(const Vec3&)>& is_free,
                                   int first_ring) {
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = std::max(1, first_ring); k <= max_rings; ++k) {
    const double radius = 0.5 * d0 * k;
    // About one point per d0/2 of circumference (per (d0/2)^2 of sphere area).
    const double ratio = radius / (0.5 * d0);
    const int points = dim == 2
                           ? static_cast<int>(std::ceil(2.0 * std::numbers::pi * ratio))
                           : static_cast<int>(std::ceil(4.0 * std::numbers::pi * ratio * ratio));
    for (int m = 0; m < points; ++m) {
      Vec3 direction;
      if (dim == 2) {
        const double angle = 2.0 * std::numbers::pi * (m + 0.5) / points;
        direction = Vec3(std::cos(angle), std::sin(angle), 0.0);
      } else {
        const double z = 1.0 - 2.0 * (m + 0.5) / points;
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        direction = Vec3(s * std::cos(golden_angle * m), s * std::sin(golden_angle * m), z);
      }
      const Vec3 y = x + radius * direction;
      if (is_free(y)) return y;
    }
  }
  return std::nullopt;
}

std::optional<Vec3> find_free_place(const Vec3& x, int dim, double d0, const FreePlaceTests& tests,
                                    bool nearby_first) {
  // The first sphere no search has tried for room or a hole.
  const int untested = nearby_first ? kNearbyRings + 1 : 1;
  std::optional<Vec3> spot;
  if (nearby_first) {
    spot = find_free_spot(x, dim, d0, kNearbyRings, tests.with_room);
    if (!spot) spot = find_free_spot(x, dim, d0, kNearbyRings, tests.hole);
  }
  if (!spot) spot = find_free_spot(x, dim, d0, kWideRings, tests.with_room, untested);
  if (!spot) spot = find_free_spot(x, dim, d0, kWideRings, tests.hole, untested);
  if (!spot) spot = find_free_spot(x, dim, d0, kWideRings, tests.clear_of_solids);
  return spot;
}

}  // namespace washout
