#pragma once
// Pairs of particles closer than a cutoff, from a uniform grid of cells of that size, for
// body-body contact. Cells are found by sorting the particles by cell key (no dense grid, so
// bodies far apart cost nothing); pairs come out in a deterministic order.
#include <cstdint>
#include <vector>

#include "engine/rigid/vec3_array.hpp"

namespace washout::contact {

struct ParticlePair {
  std::int32_t i = 0, j = 0;  // indices into the positions given, i < j
};

class ParticlePairGrid {
 public:
  // All pairs (i, j), i < j, with |x_i - x_j| < cutoff and group[i] != group[j] (particles of
  // one body never pair). dim 2 searches the x-y plane only.
  void find_pairs(const rigid::Vec3Array& position, const std::vector<std::int32_t>& group,
                  double cutoff, int dim, std::vector<ParticlePair>& pairs);

 private:
  struct Entry {
    std::uint64_t key;
    std::int32_t index;
  };
  std::vector<Entry> sorted_;
};

}  // namespace washout::contact
