#include "engine/sim/added_mass_coupling.hpp"

#include "engine/rigid/mass_properties.hpp"

namespace washout {

rigid::BodyModel with_added_mass(const rigid::BodyModel& model, const AddedMass& added) {
  rigid::BodyModel effective = model;
  rigid::set_mass_properties(
      effective, {model.mass + added.mass, model.centre_of_mass, model.inertia + added.inertia});
  return effective;
}

rigid::BodyLoad added_mass_load(const rigid::BodyLoad& fluid, const AddedMass& added,
                                const rigid::BodyState& now, const rigid::BodyState& previous,
                                double previous_dt, const Vec3& gravity) {
  Vec3 acceleration = Vec3::Zero(), angular_acceleration = Vec3::Zero();
  if (previous_dt > 0.0) {
    acceleration = (now.velocity - previous.velocity) / previous_dt;
    angular_acceleration = (now.angular_velocity - previous.angular_velocity) / previous_dt;
  }
  const Eigen::Matrix3d R = now.orientation.toRotationMatrix();
  rigid::BodyLoad load = fluid;
  load.force += added.mass * (acceleration - gravity);
  load.torque += R * added.inertia * R.transpose() * angular_acceleration;
  return load;
}

}  // namespace washout
