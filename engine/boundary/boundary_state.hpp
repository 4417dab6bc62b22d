#pragma once
// The boundary as the fluid sees it (METHOD.md "Walls": virtual markers), split by lifetime:
// what the scene fixes for the run, and what every step refills. The fluid stages read both; the
// boundary stages (virtual_markers, wall_acceleration, squeeze_film) write the second.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace washout {

// Fixed for the run.
struct WallConditions {
  std::vector<double> slip;       // slip ratio per boundary particle (0 no-slip, 1 free-slip)
  double separation_speed = 0.0;  // fluid leaving a wall faster than this separates from it
  // Wall condition of the PPE: false, the Neumann jump from the relative velocity; true, the
  // wall's velocity enters the divergence and the jump carries the wall's acceleration.
  bool dynamic = false;
  // A scene without walls (unit tests of the fluid alone).
  static const WallConditions& none() {
    static const WallConditions empty;
    return empty;
  }
};

// Refilled every step.
struct BoundaryWork {
  std::array<std::vector<double>, 3> marker_velocity;    // virtual-marker velocity (boundary)
  std::array<std::vector<double>, 3> wall_acceleration;  // (all particles; boundary entries)
  // 1: a fluid particle in a squeeze film between a body and another solid (empty: none). Such
  // particles are not unknowns of the PPE: they take film_pressure (squeeze_film.hpp).
  std::vector<std::uint8_t> film;
  std::vector<double> film_pressure;
  bool in_film(std::size_t i) const { return !film.empty() && film[i]; }
};

}  // namespace washout
