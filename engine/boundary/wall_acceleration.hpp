#pragma once
// The acceleration a_w of each boundary particle over the last step, for the wall condition of
// the PPE dP/dn = rho0 (g - a_w).n (wall_pressure = "dynamic", isph_stages.hpp). Prescribed
// walls and bodies take it from their velocities, a_w = (u_w^{n+1} - u_w^n) / dt, but only where
// the wall pushes: a wall that pulls away from the fluid (a_w . n < 0) would make the fluid
// follow it under tension, which water cannot carry (a gate lifted at free-fall speed would suck
// the outflow against its lower edge); it leaves the fluid to separate instead. Dynamic bodies'
// new velocities are solved with the pressure (implicit_body_coupling.hpp): zero here.
#include <array>
#include <cstdint>
#include <vector>

#include "engine/boundary/boundary_state.hpp"
#include "engine/core/particles.hpp"

namespace washout {

// solved_body[b] = 1 for the bodies whose acceleration the coupling solves. previous holds the
// boundary velocities of the last call (empty on the first: a_w = 0) and is updated.
void update_wall_accelerations(const Particles& p, const std::vector<std::uint8_t>& solved_body,
                               double dt, std::array<std::vector<double>, 3>& previous,
                               BoundaryWork& work);

}  // namespace washout
