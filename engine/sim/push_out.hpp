#pragma once
// Fluid found inside a solid (a wall or a body), pressed through a closing gap, is put back
// outside it: left inside, its pressure equation would see walls all round and throw it out at
// any speed. It moves along the surface normal to `clearance` outside, and its velocity loses
// the part that would take it back in, relative to the solid's velocity where it lands.
#include "engine/core/vec3.hpp"

namespace washout {

// x lies `distance` (< 0) from the solid's surface, whose outward normal there is `normal`;
// solid_velocity_at(y) is the solid's velocity at point y.
template <class VelocityAt>
void push_out_of_solid(Vec3& x, Vec3& u, double distance, const Vec3& normal, double clearance,
                       VelocityAt&& solid_velocity_at) {
  x += (clearance - distance) * normal;
  const double inward = (u - solid_velocity_at(x)).dot(normal);
  if (inward < 0.0) u -= inward * normal;
}

}  // namespace washout
