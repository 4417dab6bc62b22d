#include "engine/contact/body_rest.hpp"

namespace washout::contact {

bool body_at_rest(const rigid::BodyModel& model, const rigid::BodyState& state,
                  const rigid::BodyLoad& fluid, const rigid::BodyLoad& contact, const Vec3& gravity,
                  double dt) {
  const double g = gravity.norm(), radius = model.bounding_radius;
  const double speed = state.velocity.norm() + state.angular_velocity.norm() * radius;
  if (!(speed == 0.0 || speed < kRestSpeed * g * dt)) return false;  // NaN too
  const double weight = model.mass * g;
  const Vec3 net_force = fluid.force + contact.force + model.mass * gravity;
  const Vec3 net_torque = fluid.torque + contact.torque;
  return net_force.norm() <= kRestLoad * weight && net_torque.norm() <= kRestLoad * weight * radius;
}

bool RestWatch::observe(std::span<const rigid::BodyModel> models,
                        std::span<const rigid::BodyState> states,
                        std::span<const rigid::BodyLoad> fluid_loads,
                        std::span<const rigid::BodyLoad> contact_loads, const Vec3& gravity,
                        double dt, bool dry) {
  if (steps_ <= 0) return false;
  if (asleep()) return false;
  bool any_dynamic = false, still = dry;
  for (std::size_t b = 0; b < models.size() && still; ++b) {
    if (models[b].motion == rigid::MotionKind::kPrescribed) still = false;
    if (models[b].motion != rigid::MotionKind::kDynamic) continue;
    any_dynamic = true;
    still = body_at_rest(models[b], states[b], fluid_loads[b], contact_loads[b], gravity, dt);
  }
  still_ = still && any_dynamic ? still_ + 1 : 0;
  return asleep();
}

}  // namespace washout::contact
