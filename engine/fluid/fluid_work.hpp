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
  // The pressure gradient's scale s_i = 1 / m_i by the particle's own neighbours and where it came
  // from: 1 measured (a full support), 2 and 3 the mean of the level before among the neighbours,
  // 0 none (s = 1) (gradient_scale.cpp); empty when the lattice normalisation alone is used.
  std::vector<double> gradient_scale;
  std::vector<double> gradient_moment;  // m_i of every fluid particle, measured before the scale
  std::vector<std::uint8_t> gradient_scale_level;
  std::vector<double> gradient_scale_pending;  // scratch of the levels 2 and 3
  BoundaryWork boundary;              // markers, wall accelerations, squeeze films of this step
  std::vector<std::int32_t> unknown;  // PPE row of a fluid particle, or -1
  CsrMatrix matrix;
  std::vector<double> rhs, solution;
  // density_kick = "positions" (density_kick.cpp): the assembly keeps the density term's share
  // of the right-hand side alone; its pressure (per fluid particle) and the velocity it gave.
  bool keep_density_rhs = false;
  std::vector<double> density_rhs, density_solution, density_pressure;
  std::array<std::vector<double>, 3> density_kick;
};

// The pair factor (s_i + s_j)/2 of the gradient scale; s_j = s_i for a boundary neighbour, and 1
// where no scale is kept (the lattice normalisation alone).
inline double gradient_pair_scale(const FluidWork& work, std::size_t n, std::size_t i,
                                  std::size_t j) {
  if (work.gradient_scale.empty()) return 1.0;
  const double s_i = work.gradient_scale[i];
  return j < n ? 0.5 * (s_i + work.gradient_scale[j]) : s_i;
}

}  // namespace washout
