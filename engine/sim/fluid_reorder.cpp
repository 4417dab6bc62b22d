// The fluid kept in cell order in memory (the reorder stage, every reorder_interval steps;
// engine/core/particle_order.hpp says why). The frames list the particles by id whatever the
// order (run_file_writer.cpp). Everything the run holds per fluid particle from one step to the
// next moves with the particles; what a step rebuilds (lists, marks, the matrix) is rebuilt in the
// new order.
#include <numeric>

#include "engine/sim/simulation.hpp"

namespace washout {

void Simulation::reorder_fluid() {
  // Cells of h, the neighbour grid's: a particle's neighbours lie within two of them.
  apply_fluid_order(fluid_cell_order(particles_, ctx_.h));
}

void Simulation::apply_fluid_order(const FluidOrder& order) {
  if (is_identity(order)) return;
  permute_fluid(particles_, order);
  std::vector<double> reals;
  permute_prefix(work_.eddy_viscosity, order, reals);
  permute_prefix(work_.surface_strain, order, reals);
  for (auto& v : previous_wall_velocity_) permute_prefix(v, order, reals);
  std::vector<std::uint8_t> bytes;
  permute_prefix(inside_wall_, order, bytes);
  auto warm = coupling_.warm_start();
  for (auto& field : warm) permute_prefix(field, order, reals);
  coupling_.set_warm_start(std::move(warm));
  const std::vector<std::uint32_t> new_index = inverse_order(order);
  for (auto& i : retired_) i = new_index[i];
  // A BoomerAMG hierarchy kept across steps belongs to the old numbering of the rows.
  solver_.reset();
  fluid_reordered_ = false;
  for (std::size_t i = 0; i < particles_.fluid_count && !fluid_reordered_; ++i)
    fluid_reordered_ = particles_.id[i] != i;
}

}  // namespace washout
