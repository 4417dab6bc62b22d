#pragma once
// Cell linked list (Monaghan & Gingold 1983), METHOD.md "Neighbour search". Particles are
// bucketed by a counting sort into cells of half the interaction radius (h for a support of 2h);
// a search visits the cells within two of the point's own, a box of 5 x 5 (x 5) cells, 42 %
// less volume in 3D than the 3 x 3 x 3 cells of a full radius would hold, so fewer candidates
// are tested for the same neighbours. A neighbour list in compressed rows (CSR) is then built
// for the particles that need one (usually the fluid).
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/core/periodic_box.hpp"
#include "engine/core/row_blocks.hpp"

namespace washout {

// Neighbours of particle i are index[offset[i] .. offset[i+1]) (i itself excluded).
struct NeighborList {
  std::vector<std::uint64_t> offset;
  std::vector<std::uint32_t> index;
  std::size_t size() const { return offset.empty() ? 0 : offset.size() - 1; }
  std::size_t pair_count() const { return index.size(); }
};

class NeighborGrid {
 public:
  // Buckets all particles for searches within `radius` (the interaction radius, 2h).
  void build(const Particles& particles, double radius, const PeriodicBox& periodic);

  // Calls visit(j) for every particle j in the cells around point p (candidates, not filtered
  // by distance). Distances must then be taken with the periodic minimum image.
  template <class Visit>
  void for_each_candidate(const double p[3], Visit&& visit) const;

  // The same for the candidates with index below `limit` only (the fluid).
  template <class Visit>
  void for_each_candidate_below(const double p[3], std::uint32_t limit, Visit&& visit) const;

  // The particles with index below `limit` closer to p than sqrt(radius2) (periodic minimum
  // image) at their current positions, in for_each_candidate_below's order: written to
  // found[0, returned count), found grown as needed and never shrunk (a caller's buffer, kept
  // between searches). Tested without a branch per candidate.
  std::size_t collect_below(const Particles& particles, const double p[3], std::uint32_t limit,
                            double radius2, std::vector<std::uint32_t>& found) const;

  // CSR list of all j != i with |x_i - x_j| < radius, for i in [0, query_count).
  void build_list(const Particles& particles, std::size_t query_count, double radius,
                  NeighborList& list) const;

  const PeriodicBox& periodic() const { return periodic_; }

 private:
  // Calls visit_cell(begin, end) with ranges of sorted_ that together hold the cells within
  // kReach cells of point p's own; along a non-periodic x axis a row of them is one range.
  template <class VisitCell>
  void for_each_cell_around(const double p[3], VisitCell&& visit_cell) const;

  long cell_coordinate(double x, int axis) const;
  std::size_t cell_index(const long c[3]) const;

  static constexpr long kReach = 2;  // cells of radius / kReach: a search reaches kReach cells
  int dim_ = 2;
  double cell_size_[3] = {1, 1, 1};
  double origin_[3] = {0, 0, 0};
  long cells_[3] = {1, 1, 1};
  PeriodicBox periodic_;
  std::vector<std::uint32_t> cell_start_;  // [cell count + 2]; the last bucket: the retired
  std::vector<std::uint32_t> sorted_;      // particle indices ordered by cell
  std::vector<std::uint32_t> cell_of_;     // cell of each particle
  // The counting sort's work space, per thread's range of particles: counts per cell, then each
  // cell's first slot for the range; and the ranges' totals.
  std::vector<std::vector<std::uint32_t>> range_count_;
  std::vector<std::uint32_t> range_total_;
  std::array<std::vector<double>, 3> sorted_position_;  // x, y, z of sorted_[k] at [a][k]
  mutable RowBlocks<std::uint32_t> list_blocks_;        // build_list's work space, kept
};

template <class VisitCell>
void NeighborGrid::for_each_cell_around(const double p[3], VisitCell&& visit_cell) const {
  long c[3] = {0, 0, 0};
  for (int a = 0; a < dim_; ++a) c[a] = cell_coordinate(p[a], a);
  // The cell along a periodic axis wraps; along another, one outside the grid is skipped.
  const auto neighbour_cell = [&](int a, long offset, long& out) {
    out = c[a] + offset;
    if (periodic_.periodic[a]) {
      out = (out % cells_[a] + cells_[a]) % cells_[a];
      return true;
    }
    return out >= 0 && out < cells_[a];
  };
  const long reach_z = dim_ == 3 ? kReach : 0;
  for (long dz = -reach_z; dz <= reach_z; ++dz) {
    long n[3] = {0, 0, 0};
    if (dim_ == 3 && !neighbour_cell(2, dz, n[2])) continue;
    for (long dy = -kReach; dy <= kReach; ++dy) {
      if (!neighbour_cell(1, dy, n[1])) continue;
      if (!periodic_.periodic[0]) {
        // Cells along x are consecutive in the numbering: the row is one range.
        n[0] = std::max(c[0] - kReach, 0L);
        const std::size_t first = cell_index(n);
        n[0] = std::min(c[0] + kReach, cells_[0] - 1);
        const std::size_t last = cell_index(n);
        visit_cell(cell_start_[first], cell_start_[last + 1]);
        continue;
      }
      for (long dx = -kReach; dx <= kReach; ++dx) {
        if (!neighbour_cell(0, dx, n[0])) continue;
        const std::size_t cell = cell_index(n);
        visit_cell(cell_start_[cell], cell_start_[cell + 1]);
      }
    }
  }
}

template <class Visit>
void NeighborGrid::for_each_candidate(const double p[3], Visit&& visit) const {
  for_each_cell_around(p, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t k = begin; k < end; ++k) visit(sorted_[k]);
  });
}

template <class Visit>
void NeighborGrid::for_each_candidate_below(const double p[3], std::uint32_t limit,
                                            Visit&& visit) const {
  // A row of cells at a time, skipping the walls: stopping at a cell's first wall would need a
  // range per cell, and 125 small ranges cost more than the walls' index tests.
  const std::uint32_t* sorted = sorted_.data();  // in a local: the visits' stores cannot move it
  for_each_cell_around(p, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t k = begin; k < end; ++k)
      if (sorted[k] < limit) visit(sorted[k]);
  });
}

}  // namespace washout
