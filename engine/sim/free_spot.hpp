#pragma once
// Where to put a fluid particle caught in a closing gap. When a body lands on the floor (or a
// girder on its pier) the gap under it closes below one particle spacing; a particle still in
// it is inside one solid or the other, and pushing it out of one puts it into the other (it
// then jumps between the two every step, seen as fluid under a resting box). It is moved to
// the nearest free place instead: mass is kept, the gap is left empty.
#include <functional>
#include <optional>

#include "engine/core/vec3.hpp"

namespace washout {

// The nearest point to x, searched on circles (2D) or spheres (3D) of radius k d0/2,
// k = first_ring .. max_rings, that `is_free` accepts; none if no tested point is free.
// The directions are evenly spread (a Fibonacci sphere in 3D), so the search has no preferred
// side; the first free point of the smallest radius wins.
std::optional<Vec3> find_free_spot(const Vec3& x, int dim, double d0, int max_rings,
                                   const std::function<bool(const Vec3&)>& is_free,
                                   int first_ring = 1);

// What makes a place free, best first: a hole with room for one more particle (it arrives at
// no more than the water's density), any hole (no particle within d0/2), any place clear of
// the solids with fluid about it.
struct FreePlaceTests {
  std::function<bool(const Vec3&)> with_room, hole, clear_of_solids;
};

// Where a particle at x goes. A closing gap's way out may be far: room, then a hole, then a
// place clear of the solids, each searched to 20 d0 (kWideRings). With `nearby_first` (a
// particle put back onto another) room and then a hole within 4 d0 (kNearbyRings, past the
// kernel's support) come first: searched widely, the first room under deep water is the free
// surface, and the particle would be carried up through the water (docs/performance.md,
// fortieth session). The wide searches after them start past the spheres they tested: a point
// with room is a hole too, so none of those spheres holds either.
constexpr int kNearbyRings = 8;
constexpr int kWideRings = 40;  // wider than the gaps bodies close
std::optional<Vec3> find_free_place(const Vec3& x, int dim, double d0, const FreePlaceTests& tests,
                                    bool nearby_first);

}  // namespace washout
