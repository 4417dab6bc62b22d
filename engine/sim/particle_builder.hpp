#pragma once
// Turns the model's shapes into particles on the global lattice (walls first decide where fluid
// may not go), and refuses impossible scenes before any step is taken.
#include "engine/boundary/moving_walls.hpp"
#include "engine/core/particles.hpp"
#include "engine/model/model.hpp"

namespace washout {

struct BuiltParticles {
  Particles particles;
  std::vector<MovingWall> moving_walls;
  std::vector<double> wall_slip;  // per boundary particle
};

// Throws SceneError naming the region or wall that is wrong.
BuiltParticles build_particles(const Model& model);

}  // namespace washout
