// Cost of the contact sub-steps. Two girders:
// - the paper's PLA girder (0.3 x 0.03 x 0.02 m, d0 = 5 mm, E = 5e9 Pa, nu = 0.28, eps = 0.8)
//   resting on a floor and on a pier, fluid step 0.5 ms;
// - the girder of scripts/flume.lua at the paper's spacing (0.24 x 0.48 x 0.06 m, spanning the
//   flume wall to wall, on a 0.12 x 0.12 m pier), as `washout run scenes/girder_washout.lua
//   --set d0=0.005` holds it at rest, fluid step 1 ms.
// Prints sub-steps per fluid step, wall time per fluid step, and nanoseconds per sub-step per
// contact (surface) particle and per near particle. Figures only; nothing is asserted.
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include "engine/contact/contact_substepper.hpp"
#include "engine/rigid/lattice_body.hpp"

using namespace washout;

namespace {

contact::BoxObstacle box_between(const Vec3& lower, const Vec3& upper) {
  contact::BoxObstacle box;
  box.centre = 0.5 * (lower + upper);
  box.half_size = 0.5 * (upper - lower);
  return box;
}

void time_case(const char* name, const rigid::BodyModel& girder, const contact::ContactScene& scene,
               const Vec3& position, double dt) {
  std::vector<rigid::BodyModel> models{girder};
  std::vector<rigid::BodyState> states{rigid::initial_state(girder)};
  states[0].position = position;
  std::vector<rigid::BodyLoad> fluid(1);
  contact::ContactWorkspace workspace;
  const Vec3 gravity(0, 0, -9.81);
  for (int n = 0; n < 2; ++n)  // settle
    contact::advance_bodies(models, states, fluid, scene, workspace, gravity, n * dt, dt);
  const int steps = 10;
  long substeps = 0;
  int touching = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int n = 0; n < steps; ++n) {
    const contact::SubstepReport r =
        contact::advance_bodies(models, states, fluid, scene, workspace, gravity, (n + 2) * dt, dt);
    substeps += r.substeps;
    touching = r.most_touching;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double particles = static_cast<double>(girder.contact_offset.size());

  std::size_t near = 0;
  for (const auto& list : workspace.near_wall) near += list.particle.size();
  std::printf(
      "girder on %s: %d touching, %zu near, %ld sub-steps per fluid step, %.2f ms per fluid step, "
      "%.1f ns per sub-step per contact particle (%zu contact particles), %.1f ns per near "
      "particle\n",
      name, touching, near, substeps / steps, 1e3 * seconds / steps,
      1e9 * seconds / (substeps * particles), girder.contact_offset.size(),
      near > 0 ? 1e9 * seconds / (substeps * double(near)) : 0.0);
}

}  // namespace

int main() {
  const Vec3 size(0.3, 0.03, 0.02);
  rigid::BodyModel girder =
      rigid::make_body_model(rigid::lattice_box(3, 0.005, -0.5 * size, 0.5 * size, 1161.0));
  for (int case_index = 0; case_index < 3; ++case_index) {
    contact::ContactScene scene;
    const int pla = scene.materials.add({"pla", 5e9, 0.28, 0.8});
    scene.materials.set_friction(pla, pla, 0.05);
    const char* name = "floor";
    if (case_index == 0) {
      scene.walls.push_back({"floor", contact::PlaneWall{Vec3::Zero(), Vec3::UnitZ()}, pla});
    } else {
      contact::BoxObstacle pier;
      pier.centre = Vec3(0, 0, -0.5);
      pier.half_size = Vec3(0.025, 0.1, 0.5);
      scene.walls.push_back({"pier", pier, pla});
      name = "pier";
    }
    if (case_index == 2) {  // the flume around it: 4 side walls out of reach, plus the floor
      name = "pier in a flume (6 walls)";
      for (const Vec3& n : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)})
        scene.walls.push_back({"side", contact::PlaneWall{-0.5 * n, n}, pla});
      scene.walls.push_back({"floor", contact::PlaneWall{Vec3(0, 0, -1), Vec3::UnitZ()}, pla});
    }
    time_case(name, girder, scene, Vec3(0, 0, 0.01), 5e-4);
  }

  // scripts/flume.lua's girder at d0 = 5 mm: its ends touch the glass side walls (the flume, one
  // wall of five slabs) with no overlap, its bottom rests on the pier's top.
  const double d0 = 0.005, width = 0.48, pier_top = 0.06;
  const Vec3 deck(0.24, width, 0.06);
  const rigid::BodyModel flume_girder =
      rigid::make_body_model(rigid::lattice_box(3, d0, -0.5 * deck, 0.5 * deck, 1161.0));
  contact::ContactScene scene;
  const int pla = scene.materials.add({"pla", 5e9, 0.28, 0.8});
  const int glass = scene.materials.add({"glass", 7e10, 0.22, 0.8});
  scene.materials.set_friction(pla, pla, 0.05);
  scene.materials.set_friction(pla, glass, 0.0);
  const double half = 0.5 * width, far = 3.0, t = 0.05;
  auto slabs = std::make_shared<std::vector<contact::PrimitiveWall>>();
  slabs->push_back(box_between(Vec3(-far, -half - t, -t), Vec3(far, half + t, 0.0)));  // floor
  slabs->push_back(box_between(Vec3(-far, -half - t, 0.0), Vec3(far, -half, 0.6)));
  slabs->push_back(box_between(Vec3(-far, half, 0.0), Vec3(far, half + t, 0.6)));
  slabs->push_back(box_between(Vec3(-far - t, -half, 0.0), Vec3(-far, half, 0.6)));
  slabs->push_back(box_between(Vec3(far, -half, 0.0), Vec3(far + t, half, 0.6)));
  scene.walls.push_back({"flume", contact::UnionWall{slabs}, glass});
  scene.walls.push_back(
      {"pier", box_between(Vec3(-0.06, -0.06, 0.0), Vec3(0.06, 0.06, pier_top)), pla});
  time_case("the flume's pier at d0 = 5 mm", flume_girder, scene,
            Vec3(0, 0, pier_top + 0.5 * deck.z()), 1e-3);
  return 0;
}
