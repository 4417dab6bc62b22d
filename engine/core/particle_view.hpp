#pragma once
// A read-only window on particle data, for writers and the renderer.
// It never owns memory and never lets a reader change simulation state.
// Components are addressed with a stride so that both the engine's structure of arrays
// (stride 1, one array per axis) and an HDF5 [N, dim] block (stride dim) can be viewed.
#include <cstddef>
#include <cstdint>

namespace washout {

// Retired: a fluid particle that left the domain (spray thrown over a wall). It keeps its id and
// its last place, and takes no further part: the neighbour grid leaves it out, it does not move
// (docs/stability.md, the domain guard).
enum class ParticleKind : std::uint8_t {
  Fluid = 0,
  FixedWall = 1,
  MovingWall = 2,
  RigidBody = 3,
  Retired = 4
};

struct VectorView {
  const double* component[3] = {nullptr, nullptr, nullptr};  // x, y, z (z null in 2D)
  std::size_t stride = 1;
  double operator()(std::size_t i, int axis) const {
    return component[axis] ? component[axis][i * stride] : 0.0;
  }
};

struct ParticleView {
  int dim = 2;
  std::size_t count = 0;
  double time = 0.0;
  double d0 = 0.0;  // particle spacing [m]: sets the drawn particle radius
  VectorView position;
  VectorView velocity;
  const double* pressure = nullptr;    // [count] Pa, may be null
  const std::uint8_t* kind = nullptr;  // [count] ParticleKind values
  const std::int32_t* body = nullptr;  // [count] body index for kind 3, else -1; may be null
  // [count] the stable id of the particle at each index, a permutation of 0 .. count-1 (the
  // run keeps its fluid in cell order: particle_order.hpp); null: the index is the id. Frames
  // list the particles by id.
  const std::uint64_t* id = nullptr;
};

}  // namespace washout
