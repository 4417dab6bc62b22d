#pragma once
// The /bodies/NAME series of a run file (docs/output.md), one row per fluid step; vectors are
// 3 per row, the quaternion 4 (w, x, y, z).
#include <string>
#include <vector>

#include "engine/io/run_file_reader.hpp"

namespace washout::testing {

struct BodySeries {
  std::vector<double> time, position, quaternion, velocity, omega, force_fluid, force_contact,
      torque_fluid, torque_contact, angle;
};

inline BodySeries read_body_series(const io::RunFileReader& file, const std::string& name) {
  const std::string group = "/bodies/" + name + "/";
  BodySeries s;
  s.time = file.read_doubles(group + "time");
  s.position = file.read_doubles(group + "position");
  s.quaternion = file.read_doubles(group + "quaternion");
  s.velocity = file.read_doubles(group + "velocity");
  s.omega = file.read_doubles(group + "omega");
  s.force_fluid = file.read_doubles(group + "force_fluid");
  s.force_contact = file.read_doubles(group + "force_contact");
  s.torque_fluid = file.read_doubles(group + "torque_fluid");
  s.torque_contact = file.read_doubles(group + "torque_contact");
  s.angle = file.read_doubles(group + "angle");
  return s;
}

}  // namespace washout::testing
