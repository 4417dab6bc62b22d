#include "engine/core/particle_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace washout {

FluidOrder fluid_cell_order(const Particles& p, double cell_size) {
  const std::size_t n = p.fluid_count;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int a = 0; a < p.dim; ++a) {
    lo[a] = std::numeric_limits<double>::max(), hi[a] = std::numeric_limits<double>::lowest();
    for (std::size_t i = 0; i < n; ++i) {
      if (p.retired(i)) continue;
      lo[a] = std::min(lo[a], p.position[a][i]);
      hi[a] = std::max(hi[a], p.position[a][i]);
    }
    if (lo[a] > hi[a]) lo[a] = hi[a] = 0.0;  // no fluid left in the flow
  }
  // Cells per axis, and the axes from the longest extent to the shortest (ties by axis).
  std::array<std::uint64_t, 3> cells{1, 1, 1};
  for (int a = 0; a < p.dim; ++a)
    cells[a] = static_cast<std::uint64_t>(std::floor((hi[a] - lo[a]) / cell_size)) + 1;
  std::array<int, 3> axis{0, 1, 2};
  std::stable_sort(axis.begin(), axis.begin() + p.dim,
                   [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
  // key = ((c_slowest * cells_middle) + c_middle) * cells_fastest + c_fastest
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t s = 0; s < static_cast<std::int64_t>(n); ++s) {
    const auto i = static_cast<std::size_t>(s);
    std::uint64_t key = 0;
    if (p.retired(i)) {
      key = std::numeric_limits<std::uint64_t>::max();
    } else {
      for (int k = 0; k < p.dim; ++k) {
        const int a = axis[k];
        const auto c = std::min<std::uint64_t>(
            static_cast<std::uint64_t>((p.position[a][i] - lo[a]) / cell_size), cells[a] - 1);
        key = key * cells[a] + c;
      }
    }
    keyed[i] = {key, static_cast<std::uint32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());  // (key, index) pairs are distinct: a stable order
  FluidOrder order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = keyed[k].second;
  return order;
}

bool is_identity(const FluidOrder& order) {
  for (std::size_t k = 0; k < order.size(); ++k)
    if (order[k] != k) return false;
  return true;
}

FluidOrder order_of_ids(const Particles& p, const std::vector<std::uint64_t>& ids) {
  const std::size_t n = p.fluid_count;
  if (ids.size() != n)
    throw std::invalid_argument("the order names " + std::to_string(ids.size()) +
                                " fluid particles, the scene has " + std::to_string(n));
  // The fluid's ids are the indices it was built at, 0 .. n-1, in whatever order it now holds.
  std::vector<std::uint32_t> index_of(n, std::numeric_limits<std::uint32_t>::max());
  for (std::size_t i = 0; i < n; ++i) {
    if (p.id[i] >= n) throw std::invalid_argument("a fluid particle's id is not a fluid index");
    index_of[p.id[i]] = static_cast<std::uint32_t>(i);
  }
  FluidOrder order(n);
  std::vector<std::uint8_t> taken(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    if (ids[k] >= n || taken[ids[k]])
      throw std::invalid_argument("the order is not a permutation of the fluid's ids (id " +
                                  std::to_string(ids[k]) + ")");
    taken[ids[k]] = 1;
    order[k] = index_of[ids[k]];
  }
  return order;
}

void permute_fluid(Particles& p, const FluidOrder& order) {
  std::vector<double> reals;
  for (int a = 0; a < 3; ++a) {
    permute_prefix(p.position[a], order, reals);
    permute_prefix(p.velocity[a], order, reals);
    permute_prefix(p.normal[a], order, reals);
  }
  permute_prefix(p.pressure, order, reals);
  permute_prefix(p.density, order, reals);
  permute_prefix(p.wall_distance, order, reals);
  std::vector<std::uint8_t> bytes;
  permute_prefix(p.kind, order, bytes);
  std::vector<std::uint64_t> ids;
  permute_prefix(p.id, order, ids);
  std::vector<std::int32_t> ints;
  permute_prefix(p.body, order, ints);
  permute_prefix(p.group, order, ints);
}

std::vector<std::uint32_t> inverse_order(const FluidOrder& order) {
  std::vector<std::uint32_t> inverse(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) inverse[order[k]] = static_cast<std::uint32_t>(k);
  return inverse;
}

}  // namespace washout
