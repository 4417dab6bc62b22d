#pragma once
// Turns the model's shapes into particles on the global lattice (walls and bodies first decide
// where fluid may not go), and refuses impossible scenes before any step is taken.
#include "engine/boundary/moving_walls.hpp"
#include "engine/core/particles.hpp"
#include "engine/model/model.hpp"
#include "engine/sim/body_builder.hpp"

namespace washout {

struct BuiltParticles {
  Particles particles;
  std::vector<MovingWall> moving_walls;
  std::vector<double> wall_slip;  // per boundary particle
  // Rigid bodies (after the walls): body b's particles start at body_first[b].
  std::vector<BuiltBody> bodies;
  std::vector<std::size_t> body_first;
};

// Throws SceneError naming the region, wall or body that is wrong (bodies that overlap a wall
// or each other are refused).
BuiltParticles build_particles(const Model& model);

}  // namespace washout
