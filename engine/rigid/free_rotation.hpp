#pragma once
// Torque-free rotation of a 3D body over one step by splitting the free-rigid-body motion into
// exact rotations about its principal axes (symmetric Strang splitting, in the spirit of
// Dullweber, Leimkuhler & McLachlan 1997 and the NO_SQUISH scheme of Miller et al. 2002).
// Each part rotates the body about one principal axis by the exact angle, which keeps the world
// angular momentum L exactly, |L| exactly, and the kinetic energy to O(dt^2) without drift
// (the scheme is symplectic and time-reversible).
#include <Eigen/Geometry>

#include "engine/core/vec3.hpp"
#include "engine/rigid/body_model.hpp"

namespace washout::rigid {

// q after a torque-free interval dt with world angular momentum `momentum` (held: it is
// conserved). The angular velocity at the end is I_world(q')^-1 momentum.
Eigen::Quaterniond free_rotation(const BodyModel& model, const Eigen::Quaterniond& q,
                                 const Vec3& momentum, double dt);

}  // namespace washout::rigid
