#include "engine/core/particles.hpp"

#include <stdexcept>

namespace washout {

void Particles::add(ParticleKind k, const Vec3& x, const Vec3& u, std::int32_t group_index,
                    const Vec3& wall_normal, double distance_to_wall) {
  if (k == ParticleKind::Fluid) {
    if (fluid_count != size())
      throw std::logic_error("Particles::add: fluid particles must precede boundary particles");
    ++fluid_count;
  }
  for (int a = 0; a < 3; ++a) {
    position[a].push_back(a < dim ? x[a] : 0.0);
    velocity[a].push_back(a < dim ? u[a] : 0.0);
    normal[a].push_back(a < dim ? wall_normal[a] : 0.0);
  }
  pressure.push_back(0.0);
  density.push_back(0.0);
  kind.push_back(static_cast<std::uint8_t>(k));
  id.push_back(kind.size() - 1);
  body.push_back(k == ParticleKind::RigidBody ? group_index : -1);
  group.push_back(group_index);
  wall_distance.push_back(distance_to_wall);
}

ParticleView Particles::view(double time, double d0) const {
  ParticleView v;
  v.dim = dim;
  v.count = size();
  v.time = time;
  v.d0 = d0;
  for (int a = 0; a < dim; ++a) {
    v.position.component[a] = position[a].data();
    v.velocity.component[a] = velocity[a].data();
  }
  v.pressure = pressure.data();
  v.kind = kind.data();
  v.body = body.data();
  v.id = id.data();
  return v;
}

}  // namespace washout
