#pragma once
// Orientation update with a world-frame angular velocity held constant over one step
// (METHOD.md Rigid bodies, the q^{n+1} line).
#include <Eigen/Geometry>
#include <cstdint>

#include "engine/core/vec3.hpp"

namespace washout::rigid {

enum class QuaternionUpdate : std::uint8_t {
  kExactRotationVector,   // q' = exp(dt w / 2) q: the exact rotation by the angle |w| dt
  kFirstOrderNormalised,  // q' = normalise(q + dt/2 (0, w) q), as METHOD.md writes it
};

// The unit quaternion of a rotation by |phi| about phi/|phi| (series near phi = 0).
Eigen::Quaterniond quaternion_from_rotation_vector(const Vec3& phi);

// q^{n+1} for a world-frame angular velocity w (the rotation is applied on the left).
// Both updates return a unit quaternion.
Eigen::Quaterniond advance_orientation(const Eigen::Quaterniond& q, const Vec3& w, double dt,
                                       QuaternionUpdate update);

}  // namespace washout::rigid
