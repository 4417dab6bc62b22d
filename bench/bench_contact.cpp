// Cost of the contact sub-steps: the paper's PLA girder (0.3 x 0.03 x 0.02 m, d0 = 5 mm,
// E = 5e9 Pa, nu = 0.28, eps = 0.8) resting on a floor and on a pier, fluid step 0.5 ms.
// Prints sub-steps per fluid step, wall time per fluid step, and nanoseconds per sub-step per
// contact (surface) particle. Figures only; nothing is asserted.
#include <chrono>
#include <cstdio>
#include <vector>

#include "engine/contact/contact_substepper.hpp"
#include "engine/rigid/lattice_body.hpp"

using namespace washout;

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
    std::vector<rigid::BodyModel> models{girder};
    std::vector<rigid::BodyState> states{rigid::initial_state(girder)};
    states[0].position = Vec3(0, 0, 0.01);
    std::vector<rigid::BodyLoad> fluid(1);
    contact::ContactWorkspace workspace;
    const double dt = 5e-4;
    for (int n = 0; n < 2; ++n)  // settle
      contact::advance_bodies(models, states, fluid, scene, workspace, Vec3(0, 0, -9.81), n * dt,
                              dt);
    const int steps = 10;
    long substeps = 0;
    int touching = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int n = 0; n < steps; ++n) {
      const contact::SubstepReport r = contact::advance_bodies(
          models, states, fluid, scene, workspace, Vec3(0, 0, -9.81), (n + 2) * dt, dt);
      substeps += r.substeps;
      touching = r.most_touching;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double particles = static_cast<double>(girder.contact_offset.size());
    std::printf(
        "girder on %s: %d touching, %ld sub-steps per fluid step, %.2f ms per fluid "
        "step, %.1f ns per sub-step per contact particle (%zu contact particles)\n",
        name, touching, substeps / steps, 1e3 * seconds / steps,
        1e9 * seconds / (substeps * particles), girder.contact_offset.size());
  }
  return 0;
}
