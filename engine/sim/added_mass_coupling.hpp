#pragma once
// Added-mass stabilisation of the explicit fluid-body coupling (docs/bodies.md "Coupling").
// The pressure solve sees a body's velocity at the start of the step and the body then moves
// under that pressure, so an error e in its velocity comes back as -(m_f / M) e in the next
// step, m_f being the fluid's added mass: the step is unstable when m_f > M (a box of density
// 500 in water: m_f / M = 2.1, the error doubles every step). The integrator is given an
// artificial added mass m' on both sides of Newton's law, lagged on the right:
//   (M + m') a^{n+1} = M g + F_f + F_c + m' a^n,          a^n = (T^n - T^{n-1}) / dt^{n-1},
//   (I + J') alpha^{n+1} = M_f + M_c + J' alpha^n          (J' in the world frame),
// which turns the error's amplification into (m' - m_f) / (M + m'): stable for any body once
// m' > (m_f - M) / 2. Where the acceleration varies smoothly the m' terms cancel (to O(dt)),
// so the body keeps its true inertia M + m_f; at rest they vanish, so equilibria (Archimedes)
// are exact. m' = C rho0 V and J' = C rho0 (the shape's inertia per unit density), C the
// body's `added_mass` (default 1; 0 gives METHOD.md's explicit step).
#include <Eigen/Dense>

#include "engine/rigid/body_load.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/body_state.hpp"

namespace washout {

struct AddedMass {
  double mass = 0.0;                                  // m' [kg]
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // J', body frame, about the centre of mass
};

// The model the integrator and the contact law see: mass M + m', inertia I + J'.
rigid::BodyModel with_added_mass(const rigid::BodyModel& model, const AddedMass& added);

// The load to hand the integrator of the model with added mass so that its step is the one
// above: F_f + m' (a^n - g), M_f + J'_world alpha^n. `previous` is the state one step back,
// `previous_dt` that step's length (0: no history yet, a^n = 0).
rigid::BodyLoad added_mass_load(const rigid::BodyLoad& fluid, const AddedMass& added,
                                const rigid::BodyState& now, const rigid::BodyState& previous,
                                double previous_dt, const Vec3& gravity);

}  // namespace washout
