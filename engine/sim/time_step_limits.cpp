#include "engine/sim/time_step_limits.hpp"

#include <algorithm>
#include <cmath>

namespace washout {

const char* step_limit_name(StepLimit limit) {
  switch (limit) {
    case StepLimit::fixed:
      return "fixed";
    case StepLimit::advective:
      return "cfl";
    case StepLimit::viscous:
      return "viscous";
    case StepLimit::gravity:
      return "gravity";
    case StepLimit::dt_max:
      return "dt_max";
    case StepLimit::frame:
      return "frame";
  }
  return "?";
}

TimeStepChoice choose_time_step(const TimeStepInputs& in) {
  if (in.fixed_dt > 0) return {in.fixed_dt, StepLimit::fixed, in.fixed_dt};
  TimeStepChoice c{in.dt_max, StepLimit::dt_max};
  const auto limit = [&](double dt, StepLimit why) {
    if (dt < c.dt) c = {dt, why};
  };
  if (in.max_speed > 0) limit(in.cfl * in.h / in.max_speed, StepLimit::advective);
  if (in.max_viscosity > 0)
    limit(in.viscous_number * in.h * in.h / in.max_viscosity, StepLimit::viscous);
  if (in.gravity > 0) limit(0.25 * std::sqrt(in.h / in.gravity), StepLimit::gravity);
  c.unlanded_dt = c.dt;
  // Land on the next frame time with at most two equal steps (no sliver steps).
  const double remaining = in.until - in.time;
  if (remaining > 0) {
    const double steps = std::ceil(remaining / c.dt - 1e-9);
    if (steps <= 2) c.dt = remaining / steps, c.limit = StepLimit::frame;
  }
  return c;
}

}  // namespace washout
