#pragma once
// The fluid's pressure load on a body, summed over its surface particles (METHOD.md Rigid
// bodies): F_f = sum -P_i n_i dS_i,  M_f = sum r_i x (-P_i n_i dS_i),  r_i = x_i - X.
#include <span>

#include "engine/core/vec3.hpp"
#include "engine/rigid/body_load.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/body_state.hpp"
#include "engine/rigid/vec3_array.hpp"

namespace washout::rigid {

// pressure, position (world), normal (world, outward, unit) and area are per surface particle,
// all of the same length; the torque is about `centre` (the body's X). 2D: z terms are zero
// when the inputs have z = 0.
BodyLoad hydrodynamic_load(std::span<const double> pressure, const Vec3Array& position,
                           const Vec3Array& normal, std::span<const double> area,
                           const Vec3& centre);

// World positions and outward normals of the model's surface particles in `state`
// (x_i = X + R r0_i, n_i = R n0_i), in the order of model.surface_index.
void surface_positions_and_normals(const BodyModel& model, const BodyState& state,
                                   Vec3Array& position, Vec3Array& normal);

}  // namespace washout::rigid
