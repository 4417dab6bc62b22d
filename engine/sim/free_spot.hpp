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
// k = 1 .. max_rings, that `is_free` accepts; none if no tested point is free.
// The directions are evenly spread (a Fibonacci sphere in 3D), so the search has no preferred
// side; the first free point of the smallest radius wins.
std::optional<Vec3> find_free_spot(const Vec3& x, int dim, double d0, int max_rings,
                                   const std::function<bool(const Vec3&)>& is_free);

}  // namespace washout
