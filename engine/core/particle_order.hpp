#pragma once
// The fluid's order in memory (docs/performance.md "Particle order"). Neighbours in space should
// be neighbours in the arrays: every stage gathers its neighbours' values, and the pressure
// matrix's band (symmetric_product.hpp) is as narrow as the numbering is local. The lattice the
// scene fills is local at t = 0, a flow mixes it; the fluid is then sorted again by cell, the
// longest axis of its extent slowest, so that an index range is a slab across the flow (a long
// flume's band holds one cross-section of it, not one plane of its length).
//
// An order is a permutation of the fluid range: new index k holds the particle that was at
// order[k]. Boundary particles (walls, bodies) never move in the arrays.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/core/particles.hpp"

namespace washout {

using FluidOrder = std::vector<std::uint32_t>;

// The fluid sorted by cells of `cell_size`: by cell, the axes ordered from the longest extent of
// the fluid (slowest) to the shortest, and within a cell by present index (so the order depends
// only on the state, never on the threads). Retired particles go last.
FluidOrder fluid_cell_order(const Particles& particles, double cell_size);

// Whether order leaves every particle where it is.
bool is_identity(const FluidOrder& order);

// The order that puts the fluid particles whose ids are `ids` (in that order) at indices 0, 1,
// ...; throws std::invalid_argument when ids is not a permutation of the present fluid's ids.
FluidOrder order_of_ids(const Particles& particles, const std::vector<std::uint64_t>& ids);

// Applies order to the first order.size() entries of v (the fluid's); the rest stays.
template <class T>
void permute_prefix(std::vector<T>& v, const FluidOrder& order, std::vector<T>& scratch) {
  if (v.size() < order.size()) return;  // not kept for the fluid (an empty work array)
  scratch.resize(order.size());
  const std::int64_t n = static_cast<std::int64_t>(order.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < n; ++k) scratch[k] = v[order[k]];
  std::copy(scratch.begin(), scratch.end(), v.begin());
}

// Every per-particle array of particles, permuted over the fluid range.
void permute_fluid(Particles& particles, const FluidOrder& order);

// new_index[old] for every old fluid index (the inverse permutation).
std::vector<std::uint32_t> inverse_order(const FluidOrder& order);

}  // namespace washout
