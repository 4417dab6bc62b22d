#include "engine/rigid/mass_properties.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace washout::rigid {
namespace {

void shift(Vec3Array& offsets, const Vec3& by) {
  for (std::size_t i = 0; i < offsets.size(); ++i) offsets.set(i, offsets[i] + by);
}

}  // namespace

void set_mass_properties(BodyModel& model, const MassProperties& properties) {
  if (!(properties.mass > 0.0)) throw std::invalid_argument("rigid body: mass must be > 0");
  Vec3 centre = properties.centre_of_mass;
  if (model.dim == 2) centre.z() = 0.0;
  // r0_i = x_i - X: the particles stay where they are, the reference point moves.
  const Vec3 by = model.centre_of_mass - centre;
  shift(model.offset, by);
  shift(model.surface_offset, by);
  shift(model.contact_offset, by);
  model.centre_of_mass = centre;
  model.mass = properties.mass;
  double max_r2 = 0.0;
  for (std::size_t i = 0; i < model.offset.size(); ++i)
    max_r2 = std::max(max_r2, model.offset[i].squaredNorm());
  model.bounding_radius = std::sqrt(max_r2) + model.contact_radius;

  set_inertia(model, properties.inertia);
}

}  // namespace washout::rigid
