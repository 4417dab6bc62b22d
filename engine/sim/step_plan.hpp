#pragma once
// The step composed from the scene (docs/method.md "One step"): the list of stages a scene
// needs, built once when the simulation is made, run in order every step. A stage the scene
// does not need is not in the list: no bodies, no body or contact stage; no turbulence model,
// no eddy viscosity; no moving wall, no wall motion; no probe, no probe evaluation.
#include <cstdint>
#include <vector>

namespace washout {

enum class Stage : std::uint8_t {
  reorder,             // the fluid sorted by cell in memory, every reorder_interval steps
  neighbours,          // cell linked list and neighbour lists (METHOD.md "Neighbour search")
  density,             // summation density and free-surface detection
  gradient_scale,      // the pressure gradient's normalisation by each particle's neighbours
  wall_markers,        // virtual-marker velocities of the walls in reach of the fluid
  squeeze_film,        // closing gaps between a dynamic body and another solid
  turbulence,          // Smagorinsky eddy viscosity
  predictor,           // step 1: u* = u + dt (nu lap u + div tau / rho0 + g)
  wall_shear,          // law-of-the-wall stress on the first fluid layer (optional)
  moving_walls,        // prescribed wall velocities at t + dt
  prescribed_bodies,   // bodies whose motion the scene prescribes
  wall_accelerations,  // the walls' normal accelerations for the dynamic wall condition
  ppe_assembly,        // step 2: the stabilized PPE
  ppe_solve,           //         and its solution
  density_pressure,    // the density term's pressure alone, loosely (density_kick = positions)
  body_loads,          // pressure loads on the bodies (solved with them when dynamic)
  corrector,           // step 3: u = u* - dt/rho0 grad P
  surface_smoothing,   // free-surface particles take part of their neighbours' mean velocity
  surface_strain,      // the volume error near the surface, dt <div u>, before the move
  advect,              // step 4: x += dt u
  density_kick,        // the density term's velocity taken back out after the move
  shifting,            // Fickian particle shifting
  wall_positions,      // prescribed wall positions at t + dt
  bodies,              // Newton-Euler with DEM contact, sub-stepped
  clock,               // t += dt, the step report
  checks,              // guards: non-finite values, runaway speed, escaped particles
  push_out,            // fluid found inside a wall or a body, or caught in a closing gap, put back
  probes,              // the scene's probes
};

// Name of a stage in timings and reports.
const char* stage_name(Stage stage);

// What a scene uses, resolved once from its model and parameters.
struct SceneFeatures {
  bool bodies = false;             // any rigid body
  bool prescribed_bodies = false;  // a body that follows a prescribed motion
  bool dynamic_wall = false;       // walls in the divergence (docs/method.md), bodies solved with P
  bool turbulence = false;         // a sub-particle-scale model
  bool wall_friction = false;      // the law-of-the-wall stress
  bool shifting = false;           // any particle shifting
  bool surface_smoothing = false;  // XSPH on the free surface
  bool surface_strain = false;     // the density-invariance term near the surface by its strain
  bool gradient_scale = false;     // the pressure gradient normalised by each particle's support
  bool density_kick = false;       // the density term moves the particles, not their velocity
  bool moving_walls = false;       // a wall with a prescribed motion
  bool probes = false;             // any probe
  bool reorder = false;            // the fluid sorted by cell every reorder_interval steps
};

std::vector<Stage> compose_step(const SceneFeatures& features);

}  // namespace washout
