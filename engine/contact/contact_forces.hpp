#pragma once
// Finding contacts and summing their forces on the bodies (METHOD.md Contact): body particles
// (spheres, discs in 2D, of radius r = d0/2) against walls given by signed distance functions,
// and against surface particles of other bodies. Two passes per sub-step:
//   detect_contacts  - overlaps, normals and a bound on the stiffness of every body's contact,
//                      including particles near enough to touch before the fluid step ends;
//   contact_loads    - the spring-dashpot forces for a step h, summed into force and torque.
// All loops are serial and in a fixed order, so the result is deterministic.
#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/contact/contact_material.hpp"
#include "engine/contact/dem_contact.hpp"
#include "engine/contact/particle_pair_grid.hpp"
#include "engine/contact/wall.hpp"
#include "engine/rigid/body_load.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/body_state.hpp"
#include "engine/rigid/vec3_array.hpp"

namespace washout::contact {

// What does not change during a run: walls, materials, the law's settings.
struct ContactScene {
  std::vector<Wall> walls;
  MaterialTable materials;
  ContactSettings settings;
};

// One particle of a body near or in contact with a wall.
struct WallCandidate {
  std::int32_t body, wall, particle;  // particle: index into the body's contact particles
  double overlap;                     // r - sdf(x); > 0 in contact
  Vec3 normal;                        // grad sdf, out of the wall
};

// Two particles of different bodies near or in contact; body_a < body_b.
struct PairCandidate {
  std::int32_t body_a, particle_a, body_b, particle_b;
  double overlap;  // r_a + r_b - |x_a - x_b|
  Vec3 normal;     // from b's particle to a's
};

// The tangential spring of a body-body contact, kept while the pair touches.
struct PairSpring {
  std::int32_t body_a, particle_a, body_b, particle_b;
  Vec3 spring;
};

struct BodyContactSummary {
  int touching = 0;         // particle contacts with overlap > 0
  int near = 0;             // candidates: touching, or close enough to touch within the reach
  double frequency2 = 0.0;  // bound on omega^2 of this body's contact modes [1/s^2]
};

// The particles of one body that were near one wall when the list was built, and the body's
// pose then (a Verlet list with a skin): a particle left out was at least `skin` from the
// wall, so it is still out of reach while the body has moved, at any of its particles, less
// than skin - reach. Only the listed particles' distances are computed at each sub-step.
struct NearWallList {
  std::vector<std::int32_t> particle;  // ascending
  // For a UnionWall, per listed particle: the parts that can be its nearest while the list holds.
  std::vector<UnionWall::Mask> part_mask;
  Vec3 position = Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  double skin = -1.0;  // < 0: not built
};

// Contact data that changes during a run: the tangential springs (history across sub-steps
// and fluid steps) and scratch arrays. One per simulation; sized by prepare().
struct ContactWorkspace {
  // Pair laws and empty history for these bodies and walls, on the first call and whenever
  // their numbers change; otherwise nothing (a workspace belongs to one scene).
  void prepare(std::span<const rigid::BodyModel> models, const ContactScene& scene);

  int body_count = -1, wall_count = -1;
  std::vector<PairLaw> wall_law;  // [body * walls + wall]
  std::vector<PairLaw> pair_law;  // [a * bodies + b]
  // Per body: contact particles in the world (from the last detection). Only the entries that
  // detection and the loads read are current: all of a body that may meet another body or whose
  // near list is rebuilt, otherwise those of its near lists (contact_forces.cpp).
  std::vector<rigid::Vec3Array> position, velocity;
  // Per body: tangential springs against walls, [wall * contact particles + particle].
  std::vector<rigid::Vec3Array> wall_spring;
  std::vector<std::uint8_t> wall_spring_used;  // [body * walls + wall]: some spring may be != 0
  std::vector<NearWallList> near_wall;         // [body * walls + wall]
  std::vector<PairSpring> pair_spring, next_pair_spring;  // sorted by (a, i, b, j)

  std::vector<WallCandidate> wall_candidates;
  std::vector<PairCandidate> pair_candidates;
  std::vector<int> wall_touching;  // [body * walls + wall]
  std::vector<int> pair_touching;  // [a * bodies + b]
  std::vector<BodyContactSummary> summary;

  std::vector<double> wall_centre_distance;      // [body * walls + wall]: signed, this sub-step
  std::vector<std::uint8_t> involved;            // [body]: may meet another body
  std::vector<Eigen::Matrix3d> inertia_inverse;  // [body]: world frame, this sub-step
  ParticlePairGrid grid;
  rigid::Vec3Array gathered_position;
  std::vector<std::int32_t> gathered_body, gathered_particle;
  std::vector<ParticlePair> pairs;
};

// Contacts of all bodies in `states`. reach[b] is how far any particle of body b can move
// before the next detection; particles within it of a partner are "near" and enter the
// stiffness bound. Walls act on dynamic bodies; body pairs need one dynamic body.
void detect_contacts(std::span<const rigid::BodyModel> models,
                     std::span<const rigid::BodyState> states, const ContactScene& scene,
                     std::span<const double> reach, ContactWorkspace& workspace);

// Contact force and torque (about X) on every body for a step h, from the last detection;
// advances the tangential springs. Loads on fixed and prescribed bodies are reported too.
void contact_loads(std::span<const rigid::BodyModel> models,
                   std::span<const rigid::BodyState> states, const ContactScene& scene, double h,
                   ContactWorkspace& workspace, std::vector<rigid::BodyLoad>& loads);

}  // namespace washout::contact
