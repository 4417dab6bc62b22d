#pragma once
// Walls whose motion is prescribed as a function of time (a gate lifted at free-fall speed).
// Each moving wall translates rigidly: x = x_ref + displacement(t), u = velocity(t).
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/model/model.hpp"

namespace washout {

struct MovingWall {
  std::size_t wall_index = 0;            // into Model::walls
  std::vector<std::uint32_t> particles;  // its boundary particles
  std::vector<Vec3> reference;           // their positions at t = 0
  WallMotion motion;
  Vec3 displacement = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
};

// Evaluates the motion at time t; returns false if it is not finite.
bool evaluate_wall_motion(MovingWall& wall, double t);
// Sets the particles' velocity (before the pressure solve: the Neumann condition needs the wall
// velocity at the new time) or their position (after the fluid has moved) from the evaluated
// motion.
void set_wall_velocity(const MovingWall& wall, Particles& p);
void set_wall_position(const MovingWall& wall, Particles& p);

}  // namespace washout
