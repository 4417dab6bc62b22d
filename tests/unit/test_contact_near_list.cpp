// The near-wall lists of the contact detection (a Verlet list with a skin): at every detection
// the candidates must be exactly those a search over all of the body's particles finds (same
// particles, same overlaps, same order), while the body moves and turns so that the lists are
// rebuilt along the way, and a body at rest must search only the particles near the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/contact/contact_forces.hpp"
#include "engine/rigid/lattice_body.hpp"

namespace washout::contact {
namespace {

using rigid::BodyModel;
using rigid::BodyState;

struct Candidate {
  int wall, particle;
  double overlap;
};

// Every particle of the body within `reach` of a wall, by brute force.
std::vector<Candidate> all_candidates(const BodyModel& model, const BodyState& state,
                                      const ContactScene& scene, double reach) {
  rigid::Vec3Array x;
  rigid::particle_positions(state, model.contact_offset, x);
  std::vector<Candidate> found;
  for (int w = 0; w < static_cast<int>(scene.walls.size()); ++w)
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double gap = signed_distance(scene.walls[w].shape, x[i]) - model.contact_radius;
      if (gap < reach) found.push_back({w, static_cast<int>(i), -gap});
    }
  return found;
}

ContactScene floor_and_pier() {
  ContactScene scene;
  const int material = scene.materials.add({"body", 1e8, 0.3, 0.5});
  scene.walls.push_back({"floor", PlaneWall{Vec3::Zero(), Vec3::UnitZ()}, material});
  BoxObstacle pier;
  pier.centre = Vec3(0.2, 0.0, 0.05);
  pier.half_size = Vec3(0.03, 0.2, 0.05);
  pier.rotation = Eigen::AngleAxisd(0.3, Vec3::UnitZ()).toRotationMatrix();
  scene.walls.push_back({"pier", pier, material});
  return scene;
}

TEST(ContactNearList, CandidatesEqualAFullSearchWhileTheBodyMovesAndTurns) {
  BodyModel model = rigid::make_body_model(
      rigid::lattice_box(3, 0.005, Vec3(-0.06, -0.02, -0.015), Vec3(0.06, 0.02, 0.015), 500.0));
  model.material = 0;
  const ContactScene scene = floor_and_pier();
  std::vector<BodyModel> models{model};
  std::vector<BodyState> states{rigid::initial_state(model)};
  ContactWorkspace ws;
  ws.prepare(models, scene);
  const double reach = 0.002;
  int compared = 0;
  for (int n = 0; n < 400; ++n) {
    // Slides along the floor towards the pier, bobbing and turning about a tilted axis.
    const double t = 0.002 * n;
    BodyState& s = states[0];
    s.position = Vec3(0.5 * t, 0.01 * std::sin(9.0 * t), 0.016 + 0.004 * std::sin(7.0 * t));
    s.orientation =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.8 * t, Vec3(0.2, 0.3, 1.0).normalized()));
    const std::vector<double> reach_of{reach};
    detect_contacts(models, states, scene, reach_of, ws);
    const std::vector<Candidate> expected = all_candidates(model, s, scene, reach);
    ASSERT_EQ(ws.wall_candidates.size(), expected.size()) << "detection " << n;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(ws.wall_candidates[k].wall, expected[k].wall) << "detection " << n;
      EXPECT_EQ(ws.wall_candidates[k].particle, expected[k].particle) << "detection " << n;
      EXPECT_DOUBLE_EQ(ws.wall_candidates[k].overlap, expected[k].overlap) << "detection " << n;
    }
    compared += static_cast<int>(expected.size());
  }
  std::printf("candidates compared over 400 detections: %d\n", compared);
  EXPECT_GT(compared, 1000);  // the body did meet both walls
}

TEST(ContactNearList, ABodyAtRestSearchesOnlyItsBottomLayers) {
  BodyModel model = rigid::make_body_model(
      rigid::lattice_box(3, 0.005, Vec3(-0.05, -0.05, -0.025), Vec3(0.05, 0.05, 0.025), 500.0));
  model.material = 0;
  ContactScene scene;
  scene.materials.add({"body", 1e8, 0.3, 0.5});
  scene.walls.push_back({"floor", PlaneWall{Vec3::Zero(), Vec3::UnitZ()}, 0});
  std::vector<BodyModel> models{model};
  std::vector<BodyState> states{rigid::initial_state(model)};
  states[0].position = Vec3(0, 0, 0.025);  // bottom particles at z = 2.5 mm: touching
  ContactWorkspace ws;
  ws.prepare(models, scene);
  const std::vector<double> reach{1e-4};
  for (int n = 0; n < 3; ++n) detect_contacts(models, states, scene, reach, ws);
  const std::size_t listed = ws.near_wall[0].particle.size();
  std::printf("listed %zu of %zu particles; candidates %zu\n", listed, model.contact_offset.size(),
              ws.wall_candidates.size());
  EXPECT_EQ(ws.wall_candidates.size(), all_candidates(model, states[0], scene, 1e-4).size());
  // The skin (reach + one contact radius) holds the bottom face only: its 20 x 20 particles,
  // all touching, of the 1408 on the box's surface.
  EXPECT_EQ(listed, ws.wall_candidates.size());
  EXPECT_LT(listed, model.contact_offset.size() / 3);
}

}  // namespace
}  // namespace washout::contact
