#pragma once
// Mass properties of a whole solid given to a body whose particles are only part of it
// (METHOD.md Rigid bodies: "inertia ... from its particles or its geometry"). A body in the
// flow keeps as particles only the outer layers the fluid can see; its mass, centre of mass and
// inertia are those of the full solid, integrated from the shape (engine/sim/body_builder.hpp).
#include <Eigen/Dense>

#include "engine/core/vec3.hpp"
#include "engine/rigid/body_model.hpp"

namespace washout::rigid {

struct MassProperties {
  double mass = 0.0;                                  // M [kg] (2D: kg/m)
  Vec3 centre_of_mass = Vec3::Zero();                 // reference pose [m]
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre of mass, body frame
};

// Replaces the model's mass, centre of mass and inertia (with its inverse and principal frame)
// and recomputes the particle offsets r0_i (all, surface and contact ones) and the bounding
// radius about the new centre of mass. Particle positions in the reference pose are unchanged.
// Throws std::invalid_argument for a non-positive mass or a singular inertia.
void set_mass_properties(BodyModel& model, const MassProperties& properties);

}  // namespace washout::rigid
