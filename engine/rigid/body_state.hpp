#pragma once
// What changes every step for one rigid body (the "state" half of the model/state split), and
// the quantities read from it: world inertia, momenta, energy, particle positions/velocities.
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cstdint>
#include <span>

#include "engine/core/vec3.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/vec3_array.hpp"

namespace washout::rigid {

struct BodyState {
  Vec3 position = Vec3::Zero();                                     // X: centre of mass, world [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // q: body -> world, unit
  Vec3 velocity = Vec3::Zero();          // T: centre-of-mass velocity [m/s]
  Vec3 angular_velocity = Vec3::Zero();  // w: world frame [rad/s]; 2D: (0, 0, w_z)
};

// R(q), the rotation matrix of a unit quaternion (METHOD.md Rigid bodies, "rotation matrix
// R(q)"): body frame to world frame.
inline Eigen::Matrix3d rotation_matrix(const Eigen::Quaterniond& q) { return q.toRotationMatrix(); }

// The body where its particles were given: X = centre of mass, q = identity, at rest.
BodyState initial_state(const BodyModel& model);

// R I_body R^T (METHOD.md Rigid bodies, "world-frame inertia"); 2D: diag(0, 0, I_zz).
Eigen::Matrix3d world_inertia(const BodyModel& model, const Eigen::Quaterniond& q);
// Inverse of the world inertia; 2D: diag(0, 0, 1/I_zz).
Eigen::Matrix3d world_inertia_inverse(const BodyModel& model, const Eigen::Quaterniond& q);

Vec3 angular_momentum(const BodyModel& model, const BodyState& state);  // world, about X
Vec3 linear_momentum(const BodyModel& model, const BodyState& state);
double kinetic_energy(const BodyModel& model, const BodyState& state);  // translation+rotation

// Particle kinematics, METHOD.md Rigid bodies: x_i = X + R r0_i, u_i = T + w x (R r0_i).
// offset is any set of body-frame offsets (model.offset, model.contact_offset, ...); out arrays
// are resized to match.
void particle_positions(const BodyState& state, const Vec3Array& offset, Vec3Array& position);
void particle_velocities(const BodyState& state, const Vec3Array& offset, Vec3Array& velocity);
// The same two, for the particles listed in `which` only (the same bits as the whole-array
// forms); position and velocity must already hold offset.size() entries.
void particle_kinematics_of(const BodyState& state, const Vec3Array& offset,
                            std::span<const std::int32_t> which, Vec3Array& position,
                            Vec3Array& velocity);

}  // namespace washout::rigid
