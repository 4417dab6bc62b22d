#pragma once
// Bodies at rest held still (docs/rigid_bodies.md "Rest"). A dynamic body resting dry on fixed
// supports (the girder on its pier before the wave) is in equilibrium to round-off, yet the
// contact sub-stepper advances it through hundreds of sub-steps a fluid step (464 in the README
// wash-out) that change nothing. Once every dynamic body has stayed still and balanced for
// `steps` fluid steps with no fluid near any body, the bodies sleep: their velocities are set to
// zero and the sub-stepper is not called, their contact loads held, until fluid comes near (or
// the run restarts from a checkpoint taken asleep, which keeps the count).
#include <span>

#include "engine/rigid/body_load.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/body_state.hpp"

namespace washout::contact {

// A body is at rest after a fluid step of dt when
//  - every point of it moves slower than kRestSpeed |g| dt (a millionth of what gravity adds in a
//    step): |V| + |omega| R < kRestSpeed |g| dt, R its bounding radius;
//  - the loads on it balance to kRestLoad of its weight: |F_f + F_c + M g| < kRestLoad M |g| and
//    |M_f + M_c| < kRestLoad M |g| R.
// Without gravity no body is at rest by this test (it has no scale), unless exactly still.
inline constexpr double kRestSpeed = 1e-6;
inline constexpr double kRestLoad = 1e-6;

bool body_at_rest(const rigid::BodyModel& model, const rigid::BodyState& state,
                  const rigid::BodyLoad& fluid, const rigid::BodyLoad& contact, const Vec3& gravity,
                  double dt);

// Counts the fluid steps all bodies have been at rest and dry; `steps` of them put them to sleep
// (0: never). Bodies with a prescribed motion keep the others awake (they may push them), and
// with no dynamic body there is nothing to hold.
class RestWatch {
 public:
  explicit RestWatch(int steps = 0) : steps_(steps) {}

  // After a fluid step's advance. `dry`: no fluid was near any body at this step's loads.
  // Returns true at the step the bodies fall asleep (the caller then zeroes their velocities).
  bool observe(std::span<const rigid::BodyModel> models, std::span<const rigid::BodyState> states,
               std::span<const rigid::BodyLoad> fluid_loads,
               std::span<const rigid::BodyLoad> contact_loads, const Vec3& gravity, double dt,
               bool dry);
  bool asleep() const { return steps_ > 0 && still_ >= steps_; }
  void wake() { still_ = 0; }

  // For a checkpoint: the steps counted so far.
  int still_steps() const { return still_; }
  void restore(int still_steps) { still_ = still_steps; }

 private:
  int steps_ = 0;
  int still_ = 0;
};

}  // namespace washout::contact
