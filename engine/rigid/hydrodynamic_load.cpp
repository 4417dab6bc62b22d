#include "engine/rigid/hydrodynamic_load.hpp"

#include <stdexcept>

namespace washout::rigid {

// Hydrodynamic load, METHOD.md Rigid bodies:
//   F_f = sum -P_i n_i dS_i,   M_f = sum r_i x (-P_i n_i dS_i)
// Serial sum in particle order: deterministic, and a body surface has few particles.
BodyLoad hydrodynamic_load(std::span<const double> pressure, const Vec3Array& position,
                           const Vec3Array& normal, std::span<const double> area,
                           const Vec3& centre) {
  const std::size_t n = pressure.size();
  if (position.size() != n || normal.size() != n || area.size() != n)
    throw std::invalid_argument("hydrodynamic_load: arrays of different lengths");
  double fx = 0, fy = 0, fz = 0, mx = 0, my = 0, mz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = -pressure[i] * area[i];
    const double px = s * normal.x[i], py = s * normal.y[i], pz = s * normal.z[i];
    const double rx = position.x[i] - centre.x();
    const double ry = position.y[i] - centre.y();
    const double rz = position.z[i] - centre.z();
    fx += px;
    fy += py;
    fz += pz;
    mx += ry * pz - rz * py;
    my += rz * px - rx * pz;
    mz += rx * py - ry * px;
  }
  BodyLoad load;
  load.force = Vec3(fx, fy, fz);
  load.torque = Vec3(mx, my, mz);
  return load;
}

void surface_positions_and_normals(const BodyModel& model, const BodyState& state,
                                   Vec3Array& position, Vec3Array& normal) {
  particle_positions(state, model.surface_offset, position);
  BodyState rotation_only;
  rotation_only.orientation = state.orientation;
  particle_positions(rotation_only, model.surface_normal, normal);  // R n0_i
}

}  // namespace washout::rigid
