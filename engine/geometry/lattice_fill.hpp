#pragma once
// Fills shapes with particles on the global lattice x = (i + 1/2) d0, so that fluid, walls and
// bodies built from different shapes line up without overlapping.
#include <limits>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/geometry/shape.hpp"

namespace washout {

// Lattice points inside `shape` whose depth below its surface is at most max_depth
// (walls keep only the layers the kernel can see; pass infinity to fill the whole solid).
std::vector<Vec3> lattice_points_inside(const Shape& shape, int dim, double d0,
                                        double max_depth = std::numeric_limits<double>::infinity());

}  // namespace washout
