#pragma once
// Per-step work arrays of the projection method (cleared and refilled each step).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/solvers/sparse_matrix.hpp"

namespace washout {

struct FluidWork {
  std::array<std::vector<double>, 3> u_star;           // predicted velocity u* (fluid)
  std::array<std::vector<double>, 3> marker_velocity;  // virtual-marker velocity (boundary)
  // Free surface (fluid): 0 interior, kSurface a particle with a truncated support, kIsolated one
  // with no fluid neighbour (a drop: always P = 0).
  static constexpr std::uint8_t kSurface = 1, kIsolated = 2;
  std::vector<std::uint8_t> free_surface;
  // 1: in a squeeze film between a body and another solid (fluid; empty: none). Such particles
  // are not unknowns of the PPE: they take film_pressure (squeeze_film.hpp).
  std::vector<std::uint8_t> film;
  std::vector<double> film_pressure;
  bool in_film(std::size_t i) const { return !film.empty() && film[i]; }
  std::vector<double> eddy_viscosity;  // nu_t (fluid; empty without turbulence)
  std::vector<double> wall_slip;       // slip ratio per boundary particle
  double separation_speed = 0.0;       // fluid leaving a wall faster than this separates from it
  // Wall condition of the PPE: false, Neumann jump from the relative velocity; true, the wall's
  // velocity enters the divergence and the jump carries the wall's acceleration.
  bool dynamic_wall = false;
  std::array<std::vector<double>, 3> wall_acceleration;  // (all particles; boundary entries)
  std::vector<std::int32_t> unknown;                     // PPE row of a fluid particle, or -1
  CsrMatrix matrix;
  std::vector<double> rhs, solution;
};

}  // namespace washout
