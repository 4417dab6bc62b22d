#pragma once
// Cell linked list (Monaghan & Gingold 1983) with cells of size >= 2h, METHOD.md "Neighbour
// search". Particles are bucketed by a counting sort into cells; a neighbour list in compressed
// rows (CSR) is then built for the particles that need one (usually the fluid).
#include <cstdint>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/core/periodic_box.hpp"

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
  // Buckets all particles. cell_size must be at least the interaction radius.
  void build(const Particles& particles, double cell_size, const PeriodicBox& periodic);

  // Calls visit(j) for every particle j in the cells around point p (candidates, not filtered
  // by distance). Distances must then be taken with the periodic minimum image.
  template <class Visit>
  void for_each_candidate(const double p[3], Visit&& visit) const;

  // CSR list of all j != i with |x_i - x_j| < radius, for i in [0, query_count).
  void build_list(const Particles& particles, std::size_t query_count, double radius,
                  NeighborList& list) const;

  const PeriodicBox& periodic() const { return periodic_; }

 private:
  long cell_coordinate(double x, int axis) const;
  std::size_t cell_index(const long c[3]) const;

  int dim_ = 2;
  double cell_size_[3] = {1, 1, 1};
  double origin_[3] = {0, 0, 0};
  long cells_[3] = {1, 1, 1};
  PeriodicBox periodic_;
  std::vector<std::uint32_t> cell_start_;  // [cell count + 2]; the last bucket: the retired
  std::vector<std::uint32_t> sorted_;      // particle indices ordered by cell
  std::vector<std::uint32_t> cell_of_;     // cell of each particle
};

template <class Visit>
void NeighborGrid::for_each_candidate(const double p[3], Visit&& visit) const {
  long c[3] = {0, 0, 0};
  for (int a = 0; a < dim_; ++a) c[a] = cell_coordinate(p[a], a);
  const long lo_z = dim_ == 3 ? -1 : 0, hi_z = dim_ == 3 ? 1 : 0;
  for (long dz = lo_z; dz <= hi_z; ++dz)
    for (long dy = -1; dy <= 1; ++dy)
      for (long dx = -1; dx <= 1; ++dx) {
        long n[3] = {c[0] + dx, c[1] + dy, c[2] + dz};
        bool inside = true;
        for (int a = 0; a < dim_; ++a) {
          if (periodic_.periodic[a]) {
            n[a] = (n[a] % cells_[a] + cells_[a]) % cells_[a];
          } else if (n[a] < 0 || n[a] >= cells_[a]) {
            inside = false;
          }
        }
        if (!inside) continue;
        const std::size_t cell = cell_index(n);
        for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) visit(sorted_[k]);
      }
}

}  // namespace washout
