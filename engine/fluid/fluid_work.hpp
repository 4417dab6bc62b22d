#pragma once
// Per-step work arrays of the projection method (cleared and refilled each step). What is fixed
// for the run (wall slip, the wall condition) is in WallConditions (boundary_state.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/boundary/boundary_state.hpp"
#include "engine/solvers/sparse_matrix.hpp"

namespace washout {

struct FluidWork {
  std::array<std::vector<double>, 3> u_star;  // predicted velocity u* (fluid)
  // Free surface (fluid): 0 interior, kSurface a particle with a truncated support, kIsolated one
  // with no fluid neighbour (a drop: always P = 0).
  static constexpr std::uint8_t kSurface = 1, kIsolated = 2;
  std::vector<std::uint8_t> free_surface;
  std::vector<double> eddy_viscosity;  // nu_t (fluid; empty without turbulence)
  // Held from step to step (surface_strain.cpp): the volumetric strain each fluid particle has
  // accumulated while within a support of the free surface, 0 elsewhere; empty when not used.
  std::vector<double> surface_strain;
  BoundaryWork boundary;              // markers, wall accelerations, squeeze films of this step
  std::vector<std::int32_t> unknown;  // PPE row of a fluid particle, or -1
  CsrMatrix matrix;
  std::vector<double> rhs, solution;
};

}  // namespace washout
