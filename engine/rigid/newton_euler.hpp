#pragma once
// One explicit Newton-Euler step of a rigid body under gravity and a load held constant over
// the step (METHOD.md Rigid bodies, "Integration (explicit, per step)").
#include <cstdint>

#include "engine/core/vec3.hpp"
#include "engine/rigid/body_load.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/body_state.hpp"
#include "engine/rigid/quaternion_integrator.hpp"

namespace washout::rigid {

enum class RotationScheme : std::uint8_t {
  // METHOD.md as written: w^{n+1} = w^n + dt I^-1 (M - w^n x I w^n), I = R^n I_body R^n^T,
  // then q^{n+1} from w^{n+1}. First order; for torque-free tumbling its kinetic energy grows
  // by O(dt) per unit time (it never decreases: see docs/rigid_bodies.md).
  kExplicitEuler,
  // Same kick, on the world angular momentum: L^{n+1} = L^n + dt M, then the torque-free
  // rotation over dt by principal-axis splitting (free_rotation.hpp), w^{n+1} = I^-1 L^{n+1}.
  // Torque-free: L exact, energy bounded to O(dt^2). The default (docs/rigid_bodies.md).
  kMomentumSplitting,
};

struct IntegratorOptions {
  RotationScheme rotation = RotationScheme::kMomentumSplitting;
  QuaternionUpdate quaternion = QuaternionUpdate::kExactRotationVector;  // kExplicitEuler, 2D
};

// Advances `state` from time t to t + dt. Dynamic: T, w, X, q by METHOD.md (semi-implicit:
// X and q use the new velocities). Fixed: velocities set to zero, nothing moves. Prescribed:
// state = model.prescribed(t + dt). In 2D only x, y and the rotation about z change.
// `load` is the sum of the fluid and contact loads (torque about X); gravity is per unit mass.
void advance_body(const BodyModel& model, BodyState& state, const BodyLoad& load,
                  const Vec3& gravity, double t, double dt, const IntegratorOptions& options = {});

}  // namespace washout::rigid
