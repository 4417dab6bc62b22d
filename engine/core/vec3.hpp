#pragma once
// Small fixed-size vectors for geometry and body-level math (not for per-particle storage,
// which is structure-of-arrays in Particles).
#include <Eigen/Core>

namespace washout {
using Vec3 = Eigen::Vector3d;
}  // namespace washout
