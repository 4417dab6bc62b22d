#include "engine/boundary/moving_walls.hpp"

namespace washout {

bool evaluate_wall_motion(MovingWall& wall, double t) {
  wall.motion(t, wall.displacement, wall.velocity);
  return wall.displacement.allFinite() && wall.velocity.allFinite();
}

void set_wall_velocity(const MovingWall& wall, Particles& p) {
  for (const std::uint32_t i : wall.particles)
    for (int a = 0; a < p.dim; ++a) p.velocity[a][i] = wall.velocity[a];
}

void set_wall_position(const MovingWall& wall, Particles& p) {
  for (std::size_t k = 0; k < wall.particles.size(); ++k)
    for (int a = 0; a < p.dim; ++a)
      p.position[a][wall.particles[k]] = wall.reference[k][a] + wall.displacement[a];
}

}  // namespace washout
