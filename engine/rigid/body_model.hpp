#pragma once
// What a rigid body is, fixed for a whole run (the "model" half of the model/state split):
// its particles' offsets from the centre of mass, mass, inertia, surface description and how it
// moves (METHOD.md Rigid bodies). The part that changes every step is BodyState.
#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/rigid/vec3_array.hpp"

namespace washout::rigid {

struct BodyState;

enum class MotionKind : std::uint8_t {
  kDynamic,     // moved by gravity, fluid and contact loads (Newton-Euler)
  kFixed,       // never moves; acts on others like a wall made of particles
  kPrescribed,  // follows PrescribedMotion; loads on it are ignored
};

// Prescribed motion: the whole state (X, q, T, w) at time t. T and w must be consistent with
// X(t) and q(t): contact damping and the particle velocities use them.
using PrescribedMotion = std::function<BodyState(double t)>;

// How a particle's own extent enters the inertia tensor.
enum class ParticleInertia : std::uint8_t {
  kPointMass,  // sum m |r|^2: short of the exact box value by m d0^2/6 per particle
  kCell,       // point mass + the particle's own cube (square in 2D) m d0^2/6 per axis: exact
               // for a box filled with a cell-centred lattice
};

// What the caller gives to build a body: particle positions in the body's reference pose
// (the pose at q = identity, usually the initial world positions), a uniform particle mass,
// and optionally the surface (mask, outward normals, areas) for the hydrodynamic load.
struct BodyParticles {
  int dim = 3;                 // 2: motion in x-y, rotation about z only (z is ignored)
  double spacing = 0.0;        // d0 [m]; the contact radius is d0/2
  double particle_mass = 0.0;  // [kg] (2D: kg per metre of thickness)
  Vec3Array position;          // [n] reference positions [m]
  ParticleInertia particle_inertia = ParticleInertia::kCell;
  // Surface particles: mask [n] (1 = on the surface), with outward normals [n] (unit, reference
  // pose) and areas [n] (m^2; in 2D m per metre of thickness), read only where the mask is 1.
  // An empty mask means "no surface given": no hydrodynamic load, and every particle may touch.
  std::vector<std::uint8_t> surface;
  Vec3Array normal;
  std::vector<double> area;
};

struct BodyModel {
  std::string name;
  int dim = 3;
  double spacing = 0.0;                // d0 [m]
  double contact_radius = 0.0;         // r = d0/2 [m], METHOD.md Contact
  double particle_mass = 0.0;          // [kg]
  double mass = 0.0;                   // M [kg]
  Vec3 centre_of_mass = Vec3::Zero();  // in the reference pose [m]
  Vec3Array offset;                    // r0_i = x_i(reference) - centre_of_mass, all particles
  double bounding_radius = 0.0;        // max |r0_i| + r: a sphere about X holding every particle
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // body frame, about the centre of mass
  Eigen::Matrix3d inertia_inverse = Eigen::Matrix3d::Zero();  // 2D: only (2,2) is used
  // Principal frame (3D): inertia = axes * diag(moments) * axes^T, axes a proper rotation.
  Vec3 principal_moments = Vec3::Zero();
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();

  // Surface particles (hydrodynamic load): indices into offset, body-frame normals, areas.
  std::vector<std::int32_t> surface_index;
  Vec3Array surface_offset, surface_normal;
  std::vector<double> surface_area;
  // Particles that can touch something: the surface particles, or all when no surface given.
  std::vector<std::int32_t> contact_index;
  Vec3Array contact_offset;

  MotionKind motion = MotionKind::kDynamic;
  PrescribedMotion prescribed;  // used when motion == kPrescribed
  int material = 0;             // contact material id (contact::MaterialTable)

  std::size_t particle_count() const { return offset.size(); }
};

// Mass, centre of mass, offsets, inertia (body frame and principal) and the surface and contact
// particle lists. Throws std::invalid_argument on inconsistent input.
BodyModel make_body_model(const BodyParticles& particles);

// Sets model.inertia (body frame, about the centre of mass) and what follows from it: the
// inverse and, in 3D, the principal moments and axes (a proper rotation). Throws
// std::invalid_argument for a singular tensor (3D) or I_zz <= 0 (2D).
void set_inertia(BodyModel& model, const Eigen::Matrix3d& inertia);

}  // namespace washout::rigid
