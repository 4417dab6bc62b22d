#pragma once
// The rigid bodies of a run and their two-way coupling with the fluid (METHOD.md Rigid bodies
// and Contact; docs/bodies.md). Built only when a scene has bodies. In each fluid step:
//   1. before the pressure solve, the body particles carry the body's velocity (prescribed
//      bodies: at the new time, like moving walls), so that the wall treatment (virtual markers,
//      the Neumann condition of the PPE) sees them as walls that move;
//   2. after the solve, the surface pressure gives F_f and M_f (body_surface_pressure.hpp);
//      dynamic bodies' loads come from the pressure solved together with their velocities
//      (implicit_body_coupling.hpp), which keeps light bodies stable;
//   3. after the fluid has moved, advance_bodies integrates every body over the step with the
//      fluid load held, sub-stepped for contact with the fixed walls and between bodies;
//   4. the body particles follow: x = X + R r0, u = T + w x R r0, n = R n0.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/contact/body_rest.hpp"
#include "engine/contact/contact_substepper.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"
#include "engine/model/model.hpp"
#include "engine/rigid/rotation_angle.hpp"
#include "engine/sim/body_builder.hpp"
#include "engine/sim/body_surface_pressure.hpp"

namespace washout {

namespace io {
struct Checkpoint;
}  // namespace io

class RigidBodySystem {
 public:
  // bodies[b]'s particles are p's indices [first_particle[b], first_particle[b] + count), in the
  // order of its model's offsets. Throws SceneError for an unknown contact material.
  RigidBodySystem(const Model& model, std::vector<BuiltBody> bodies,
                  std::vector<std::size_t> first_particle);

  std::size_t size() const { return models_.size(); }
  const std::string& name(std::size_t b) const { return models_[b].name; }
  const rigid::BodyModel& model(std::size_t b) const { return models_[b]; }
  const rigid::BodyState& state(std::size_t b) const { return states_[b]; }
  const rigid::BodyLoad& fluid_load(std::size_t b) const { return fluid_loads_[b]; }
  const rigid::BodyLoad& contact_load(std::size_t b) const { return contact_loads_[b]; }
  double angle(std::size_t b) const { return angles_[b].angle(); }  // about angle_axis [rad]
  const Vec3& angle_axis(std::size_t b) const { return angles_[b].axis(); }
  double volume(std::size_t b) const { return volumes_[b]; }
  const contact::ContactScene& contact_scene() const { return contact_; }
  const contact::SubstepReport& last_substeps() const { return last_report_; }

  // Positions, velocities and normals of every body particle from the bodies' states.
  void place_particles(Particles& p) const;
  // Prescribed bodies' particle velocities at the new time t (before the pressure solve).
  void set_prescribed_velocities(double t, Particles& p) const;
  // F_f, M_f of every body from the pressure just solved (fluid not yet moved). While no fluid
  // comes near any body (dry(): the girder before the wave), the surface pressure is zero
  // without a search, the same loads.
  void compute_fluid_loads(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                           const Vec3& gravity);
  // Fluid steps the bodies have slept so far (contact/body_rest.hpp: dry, still and balanced
  // for rest_steps).
  long asleep_steps() const { return asleep_steps_; }
  // Whether, at the last compute_fluid_loads, no fluid particle lay within the kernel's support
  // (2h) of any body particle or of its surface's mirror point: the fluid's bounding box and
  // every body's, widened by that reach, apart. Never in a periodic domain.
  bool dry() const { return dry_; }
  // The load as a linear map of a pressure field on the PPE's rows (a response field or a change
  // of the pressure: no hydrostatic carry, no free-surface clamp; body_surface_pressure.hpp):
  // the fluid around the surface is searched once by build_linear_load, after the pressure
  // solve, and each linear_load is then a short sum. Not stored as the fluid load.
  void build_linear_load(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                         std::span<const std::int32_t> unknown);
  const std::vector<rigid::BodyLoad>& linear_load(const SphContext& ctx, const Particles& p,
                                                  std::span<const double> rows);
  void set_fluid_load(std::size_t b, const rigid::BodyLoad& load) { fluid_loads_[b] = load; }
  bool dynamic(std::size_t b) const { return models_[b].motion == rigid::MotionKind::kDynamic; }
  // Every body from t to t + dt with contact sub-steps, then its particles. Returns the number
  // of sub-steps (0 while the bodies sleep: contact/body_rest.hpp); throws UnstableError when a
  // body's state blows up or sub-stepping fails.
  long advance(double t, double dt, const Vec3& gravity, Particles& p);
  // The contact guard: throws UnstableError when, after the step, a body overlaps a wall or
  // another body by more than max_overlap [m] (0: no check): the contact is too soft for the
  // load or the step let a body pass through, and the loads that follow are not physical.
  void check_overlap(double max_overlap) const;
  // Whether x lies inside body b's shape in its current pose.
  bool contains(std::size_t b, const Vec3& x) const;
  // Signed distance of world point x from body b's surface (negative inside).
  double signed_distance(std::size_t b, const Vec3& x) const;
  // Velocity of body b's material point at world point x.
  Vec3 velocity_at(std::size_t b, const Vec3& x) const;
  // A point x inside body b moves out along the surface normal to `clearance` outside it, and a
  // velocity u at it loses any part that would take it back in (relative to the body). Returns
  // false (and changes nothing) if x is outside.
  bool push_out(std::size_t b, Vec3& x, Vec3& u, double clearance) const;

  // What the next step reads of the bodies, for a checkpoint (entries named body_* and
  // contact_*): states, the loads of the last step (its contact load enters the next coupling),
  // the rotation trackers and the contact springs. restore_state throws io::CheckpointError
  // when the checkpoint's bodies do not match these.
  void save_state(io::Checkpoint& c) const;
  void restore_state(const io::Checkpoint& c);

 private:
  void place_body(std::size_t b, Particles& p) const;
  // scratch_loads_ from surface_pressure_ (METHOD.md Rigid bodies).
  void loads_of_surface_pressure(const Particles& p);
  // dry() for the particles as they are now.
  bool no_fluid_near(const SphContext& ctx, const Particles& p) const;
  // x (world) in body b's reference pose, where its shape is defined.
  Vec3 reference_point(std::size_t b, const Vec3& x) const;

  int dim_ = 2;
  std::vector<rigid::BodyModel> models_;
  std::vector<rigid::BodyState> states_;
  std::vector<rigid::BodyLoad> fluid_loads_, contact_loads_, scratch_loads_;
  std::vector<rigid::RotationAngleTracker> angles_;
  std::vector<Shape> shapes_;  // in the reference pose (q = identity, X = centre of mass)
  std::vector<double> volumes_;
  std::vector<std::size_t> first_;
  std::vector<rigid::Vec3Array> reference_normal_;  // n0 per particle, body frame
  // Surface particles of all bodies (particle indices), body b's at [surface_begin_[b], [b+1]).
  std::vector<std::uint32_t> surface_particles_;
  std::vector<std::size_t> surface_begin_;
  std::vector<double> surface_pressure_;
  bool dry_ = false;
  SurfaceStencil surface_stencil_;             // build_linear_load's
  rigid::Vec3Array load_point_, load_normal_;  // scratch
  contact::ContactScene contact_;
  contact::ContactWorkspace workspace_;
  contact::SubstepReport last_report_;
  contact::RestWatch rest_;
  long asleep_steps_ = 0;
};

}  // namespace washout
