#include "engine/contact/contact_substepper.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace washout::contact {
namespace {

using rigid::BodyLoad;
using rigid::BodyModel;
using rigid::BodyState;
using rigid::MotionKind;

// How far any particle of the body can move in time tau without contact: its speed bound
// |T| + |w| R and acceleration bound |g + F/M| + (|I^-1 M| + |w|^2) R, with R the bounding
// radius. A small slack (1e-3 r) covers rounding.
double reach(const BodyModel& model, const BodyState& state, const BodyLoad& fluid,
             const Vec3& gravity, double tau) {
  if (model.motion == MotionKind::kFixed) return 0.0;
  const double radius = model.bounding_radius;
  const double w = state.angular_velocity.norm();
  const double speed = state.velocity.norm() + w * radius;
  double acceleration = 0.0;
  if (model.motion == MotionKind::kDynamic) {
    const Eigen::Matrix3d inverse = rigid::world_inertia_inverse(model, state.orientation);
    acceleration = (gravity + fluid.force / model.mass).norm() +
                   ((inverse * fluid.torque).norm() + w * w) * radius;
  }
  return speed * tau + 0.5 * acceleration * tau * tau + 1e-3 * model.contact_radius;
}

}  // namespace

// Contact sub-stepping, METHOD.md Contact (see the header for the rule).
SubstepReport advance_bodies(std::span<const BodyModel> models, std::span<BodyState> states,
                             std::span<const BodyLoad> fluid_loads, const ContactScene& scene,
                             ContactWorkspace& ws, const Vec3& gravity, double t, double dt_fluid,
                             const rigid::IntegratorOptions& options) {
  const std::size_t bodies = models.size();
  if (states.size() != bodies || fluid_loads.size() != bodies)
    throw std::invalid_argument("advance_bodies: models, states and loads differ in number");
  ws.prepare(models, scene);
  SubstepReport report;
  report.contact_load.assign(bodies, {});
  report.smallest_step = dt_fluid;
  std::vector<double> reach_of(bodies);
  std::vector<BodyLoad> contact(bodies);
  const double steps_per_contact = scene.settings.steps_per_contact;

  double elapsed = 0.0;
  // The last sub-step ends exactly at dt_fluid; the tolerance absorbs rounding of the sum.
  while (dt_fluid - elapsed > 1e-12 * dt_fluid) {
    const double remaining = dt_fluid - elapsed;
    for (std::size_t b = 0; b < bodies; ++b)
      reach_of[b] = reach(models[b], states[b], fluid_loads[b], gravity, remaining);
    detect_contacts(models, states, scene, reach_of, ws);

    double frequency2 = 0.0;
    for (std::size_t b = 0; b < bodies; ++b) {
      if (models[b].motion != MotionKind::kDynamic) continue;
      frequency2 = std::max(frequency2, ws.summary[b].frequency2);
      report.most_touching = std::max(report.most_touching, ws.summary[b].touching);
    }
    double h = remaining;
    if (frequency2 > 0.0) {
      const double t_contact = std::numbers::pi / std::sqrt(frequency2);
      const double longest = t_contact / steps_per_contact;
      const double count = std::ceil(remaining / longest * (1.0 - 1e-12));
      h = remaining / std::max(count, 1.0);
    }
    if (report.substeps >= scene.settings.max_substeps)
      throw std::runtime_error("contact sub-stepping: more than " +
                               std::to_string(scene.settings.max_substeps) +
                               " sub-steps in one fluid step (sub-step " + std::to_string(h) +
                               " s at t = " + std::to_string(t + elapsed) + " s)");

    contact_loads(models, states, scene, h, ws, contact);
    for (std::size_t b = 0; b < bodies; ++b) {
      rigid::advance_body(models[b], states[b], fluid_loads[b] + contact[b], gravity, t + elapsed,
                          h, options);
      report.contact_load[b].force += h / dt_fluid * contact[b].force;
      report.contact_load[b].torque += h / dt_fluid * contact[b].torque;
    }
    elapsed += h;
    ++report.substeps;
    report.smallest_step = std::min(report.smallest_step, h);
  }
  return report;
}

}  // namespace washout::contact
