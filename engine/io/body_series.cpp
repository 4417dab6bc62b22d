#include "engine/io/body_series.hpp"

#include <sstream>
#include <string>

#include "engine/io/run_file_writer.hpp"

namespace washout::io {

void BodySeries::record(const RigidBodySystem& bodies, double time) {
  rows_.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    Rows& out = rows_[b];
    const rigid::BodyState& s = bodies.state(b);
    auto push = [](std::vector<double>& v, const Vec3& x) {
      v.insert(v.end(), {x[0], x[1], x[2]});
    };
    out.time.push_back(time);
    push(out.position, s.position);
    const Eigen::Quaterniond& q = s.orientation;
    out.quaternion.insert(out.quaternion.end(), {q.w(), q.x(), q.y(), q.z()});
    push(out.velocity, s.velocity);
    push(out.omega, s.angular_velocity);
    push(out.force_fluid, bodies.fluid_load(b).force);
    push(out.force_contact, bodies.contact_load(b).force);
    push(out.torque_fluid, bodies.fluid_load(b).torque);
    push(out.torque_contact, bodies.contact_load(b).torque);
    out.angle.push_back(bodies.angle(b));
  }
}

void BodySeries::append_to(RunFileWriter& writer, const RigidBodySystem& bodies) {
  rows_.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const std::string group = "/bodies/" + bodies.name(b);
    if (!attributes_written_) {
      const Vec3& a = bodies.angle_axis(b);
      std::ostringstream axis, mass, volume;
      axis << a.x() << " " << a.y() << " " << a.z();
      mass.precision(17);
      mass << bodies.model(b).mass;
      volume.precision(17);
      volume << bodies.volume(b);
      writer.set_string_attribute(group, "rows",
                                  "step: one row per fluid step, the state after the step and "
                                  "the loads applied during it");
      writer.set_string_attribute(group, "angle_axis", axis.str());
      writer.set_string_attribute(group, "mass", mass.str());
      writer.set_string_attribute(group, "volume", volume.str());
    }
    Rows& s = rows_[b];
    const std::size_t count = s.time.size();
    if (count == 0) continue;
    writer.append(group + "/time", s.time.data(), count);
    writer.append(group + "/position", s.position.data(), count, 3);
    writer.append(group + "/quaternion", s.quaternion.data(), count, 4);
    writer.append(group + "/velocity", s.velocity.data(), count, 3);
    writer.append(group + "/omega", s.omega.data(), count, 3);
    writer.append(group + "/force_fluid", s.force_fluid.data(), count, 3);
    writer.append(group + "/force_contact", s.force_contact.data(), count, 3);
    writer.append(group + "/torque_fluid", s.torque_fluid.data(), count, 3);
    writer.append(group + "/torque_contact", s.torque_contact.data(), count, 3);
    writer.append(group + "/angle", s.angle.data(), count);
    for (auto* v : {&s.time, &s.position, &s.quaternion, &s.velocity, &s.omega, &s.force_fluid,
                    &s.force_contact, &s.torque_fluid, &s.torque_contact, &s.angle})
      v->clear();
  }
  attributes_written_ = true;
}

}  // namespace washout::io
