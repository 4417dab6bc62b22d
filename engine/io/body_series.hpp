#pragma once
// The per-step rows of each rigid body, /bodies/NAME (docs/bodies.md): the state after the step
// and the loads applied during it, kept from one frame to the next and appended at each frame.
#include <vector>

#include "engine/sim/rigid_body_system.hpp"

namespace washout::io {

class RunFileWriter;

class BodySeries {
 public:
  // One row per body of `bodies` at `time`.
  void record(const RigidBodySystem& bodies, double time);
  // Appends the rows kept so far and forgets them. The groups' attributes (mass, volume, ...)
  // are written with the first rows.
  void append_to(RunFileWriter& writer, const RigidBodySystem& bodies);

 private:
  struct Rows {
    std::vector<double> time, position, quaternion, velocity, omega, force_fluid, force_contact,
        torque_fluid, torque_contact, angle;
  };
  std::vector<Rows> rows_;  // per body
  bool attributes_written_ = false;
};

}  // namespace washout::io
