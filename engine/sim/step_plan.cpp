#include "engine/sim/step_plan.hpp"

namespace washout {

const char* stage_name(Stage stage) {
  switch (stage) {
    case Stage::reorder:
      return "reorder";
    case Stage::neighbours:
      return "neighbours";
    case Stage::density:
      return "density";
    case Stage::wall_markers:
      return "wall_markers";
    case Stage::squeeze_film:
      return "squeeze_film";
    case Stage::turbulence:
      return "turbulence";
    case Stage::predictor:
      return "predictor";
    case Stage::wall_shear:
      return "wall_shear";
    case Stage::moving_walls:
      return "moving_walls";
    case Stage::prescribed_bodies:
      return "prescribed_bodies";
    case Stage::wall_accelerations:
      return "wall_accelerations";
    case Stage::ppe_assembly:
      return "ppe_assembly";
    case Stage::ppe_solve:
      return "ppe_solve";
    case Stage::body_loads:
      return "body_loads";
    case Stage::corrector:
      return "corrector";
    case Stage::surface_smoothing:
      return "surface_smoothing";
    case Stage::surface_strain:
      return "surface_strain";
    case Stage::gradient_scale:
      return "gradient_scale";
    case Stage::advect:
      return "advect";
    case Stage::shifting:
      return "shifting";
    case Stage::wall_positions:
      return "wall_positions";
    case Stage::bodies:
      return "bodies";
    case Stage::density_pressure:
      return "density_pressure";
    case Stage::density_kick:
      return "density_kick";
    case Stage::clock:
      return "clock";
    case Stage::checks:
      return "checks";
    case Stage::push_out:
      return "push_out";
    case Stage::probes:
      return "probes";
  }
  return "?";
}

std::vector<Stage> compose_step(const SceneFeatures& f) {
  std::vector<Stage> plan;
  plan.reserve(32);  // every stage at most once
  if (f.reorder) plan.push_back(Stage::reorder);
  plan.insert(plan.end(), {Stage::neighbours, Stage::density});
  if (f.gradient_scale) plan.push_back(Stage::gradient_scale);  // needs the surface, for the PPE
  plan.push_back(Stage::wall_markers);
  if (f.bodies && f.dynamic_wall) plan.push_back(Stage::squeeze_film);
  if (f.turbulence) plan.push_back(Stage::turbulence);
  plan.push_back(Stage::predictor);
  if (f.wall_friction) plan.push_back(Stage::wall_shear);
  if (f.moving_walls) plan.push_back(Stage::moving_walls);
  if (f.prescribed_bodies) plan.push_back(Stage::prescribed_bodies);
  if (f.dynamic_wall) plan.push_back(Stage::wall_accelerations);
  plan.insert(plan.end(), {Stage::ppe_assembly, Stage::ppe_solve});
  if (f.density_kick) plan.push_back(Stage::density_pressure);
  if (f.bodies)
    plan.push_back(Stage::body_loads);  // P^{n+1} belongs to x^n: before the fluid moves
  plan.push_back(Stage::corrector);
  if (f.surface_smoothing) plan.push_back(Stage::surface_smoothing);
  if (f.surface_strain) plan.push_back(Stage::surface_strain);  // with the velocity that moves
  plan.push_back(Stage::advect);
  if (f.density_kick) plan.push_back(Stage::density_kick);  // before shifting, which reads u
  if (f.shifting) plan.push_back(Stage::shifting);
  if (f.moving_walls) plan.push_back(Stage::wall_positions);
  if (f.bodies) plan.push_back(Stage::bodies);
  plan.insert(plan.end(), {Stage::clock, Stage::checks, Stage::push_out});
  if (f.probes) plan.push_back(Stage::probes);
  return plan;
}

}  // namespace washout
