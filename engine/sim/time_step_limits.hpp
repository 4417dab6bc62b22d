#pragma once
// The adaptive time step and which limit set it (docs/parameters.md, reported every step in
// /stats/dt_limit and on the progress line):
//   advective  dt <= cfl h / max|u|
//   viscous    dt <= viscous_number h^2 / (nu + max nu_t)
//   gravity    dt <= 0.25 sqrt(h / |g|)  (the body-force limit: a particle falls h/32 at most)
//   dt_max     the largest step
//   frame      shortened to land on the next output frame in at most two equal steps
//   fixed      the scene's dt
// Contact is sub-stepped inside a step and never limits it: its own step, 2 pi sqrt(M/k) /
// steps_per_contact, sets the sub-step count (docs/rigid_bodies.md).
#include <cstdint>

namespace washout {

enum class StepLimit : std::uint8_t { fixed, advective, viscous, gravity, dt_max, frame };
const char* step_limit_name(StepLimit limit);

struct TimeStepInputs {
  double fixed_dt = 0.0;  // > 0: the scene's fixed step
  // The limits come from the run's parameters (SimulationParameters holds their defaults); no
  // defaults here, so that a second copy cannot drift from those. Left at 0, the step is 0 and
  // the dt_min guard stops the run.
  double cfl = 0.0, viscous_number = 0.0, dt_max = 0.0;
  double h = 0.0;
  double max_speed = 0.0;      // largest fluid speed of the last step
  double max_viscosity = 0.0;  // nu + largest eddy viscosity
  double gravity = 0.0;        // |g|
  double time = 0.0, until = 0.0;
};

struct TimeStepChoice {
  double dt = 0.0;
  StepLimit limit = StepLimit::dt_max;
  // The step before it was shortened to land on a frame (the scene's dt when fixed).
  double unlanded_dt = 0.0;
};

TimeStepChoice choose_time_step(const TimeStepInputs& in);

}  // namespace washout
