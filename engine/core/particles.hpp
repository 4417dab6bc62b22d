#pragma once
// Particle storage as a structure of arrays: one contiguous array per quantity.
// Fluid particles occupy [0, fluid_count); boundary particles (walls, bodies) follow.
// The boundary's order never changes during a run; the fluid's is sorted by cell every
// reorder_interval steps (particle_order.hpp), so a particle's stable id is `id`, its index at
// t = 0.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/core/particle_view.hpp"
#include "engine/core/vec3.hpp"

namespace washout {

struct Particles {
  int dim = 2;
  std::array<std::vector<double>, 3> position;
  std::array<std::vector<double>, 3> velocity;
  std::vector<double> pressure;
  std::vector<double> density;     // summation density <rho>_i (fluid only)
  std::vector<std::uint8_t> kind;  // ParticleKind
  std::vector<std::uint64_t> id;
  std::vector<std::int32_t> body;   // body index for rigid-body particles, else -1
  std::vector<std::int32_t> group;  // index of the wall (or body) a boundary particle belongs to
  // Boundary particles: unit normal of the nearest wall surface pointing into the fluid, and the
  // distance from the particle to that surface (both zero for fluid particles).
  std::array<std::vector<double>, 3> normal;
  std::vector<double> wall_distance;
  std::size_t fluid_count = 0;

  std::size_t size() const { return kind.size(); }
  bool is_fluid(std::size_t i) const { return i < fluid_count; }
  // A fluid particle that left the domain: in no cell of the grid, at rest, out of every sum.
  bool retired(std::size_t i) const {
    return kind[i] == static_cast<std::uint8_t>(ParticleKind::Retired);
  }
  Vec3 x(std::size_t i) const { return {position[0][i], position[1][i], position[2][i]}; }
  Vec3 u(std::size_t i) const { return {velocity[0][i], velocity[1][i], velocity[2][i]}; }

  // Appends one particle; fluid particles must all be added before any boundary particle.
  void add(ParticleKind k, const Vec3& x, const Vec3& u, std::int32_t group_index,
           const Vec3& wall_normal = Vec3::Zero(), double distance_to_wall = 0.0);

  ParticleView view(double time, double d0) const;
};

}  // namespace washout
