#pragma once
// The contact wall of a scene shape (a box, cylinder, sphere or a union of them). One primitive
// becomes the matching plain struct (BoxObstacle, CylinderObstacle), so the particle loop has
// no indirect call. A union becomes one UnionWall whose distance is the minimum over
// its primitives and whose normal is that of the nearest one: a particle over the seam of two
// touching boxes of one union (a floor made of two slabs) feels one contact, not two.
#include "engine/contact/wall.hpp"
#include "engine/geometry/shape.hpp"

namespace washout::contact {

// dim = 2: shapes lie in the x-y plane and are unbounded along z (a cylinder is a disc).
WallShape wall_shape_from(const Shape& shape, int dim);

}  // namespace washout::contact
