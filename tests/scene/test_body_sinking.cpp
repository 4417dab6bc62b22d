// A heavy box sinks in still water, lands on the floor and comes to rest on it without passing
// through (scenes/sinking_box_2d.lua), at two resolutions: about 30 s on one thread, most of
// it at d0 = 0.005 m, where the contact sub-steps (267 per fluid step) run serially.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/body_series.hpp"
#include "support/scene_runner.hpp"

namespace washout {
namespace {

// Bounds:
//  - never through the floor: the bottom (X - H/2) stays above -d0/100; the linear contact's
//    static overlap F_c / (N k_n) is about 3e-8 m here (test_body_resting.cpp), and an impact
//    at v ~ 0.5 m/s with 20 sub-steps per contact overshoots it by v t_c ~ 1e-5 m at most;
//  - at rest over the last 0.2 s: speed below 5e-3 m/s (the still water's own noise moves the
//    fluid at about 1e-2 m/s, and the box sits on stiff springs);
//  - resting on the floor: the bottom within d0/100 of it;
//  - the contact and fluid loads carry the weight: F_c + F_f = M g within 5 % (the fluid's
//    noise shakes the box a little on its springs);
//  - sub-stepped while touching: /stats/substeps above 1 at the end;
//  - the squeeze film is marked only where the gap closes: no film particle before t = 0.1 s
//    (the gap is then still over 0.03 m wide), some by the end.
TEST(SinkingBox, LandsAndRestsOnTheFloor) {
  const double B = 0.08, H = 0.04, rho_b = 2000.0, g = 9.81;
  const double weight = rho_b * B * H * g;
  for (double d0 : {0.01, 0.005}) {
    char name[64];
    std::snprintf(name, sizeof name, "sinking_box_%g", d0);
    const cli::RunOutcome outcome =
        testing::run_scene("sinking_box_2d.lua", name, {{"d0", std::to_string(d0)}});
    io::RunFileReader file(outcome.h5_path);
    const testing::BodySeries box = testing::read_body_series(file, "box");
    const auto substeps = file.read_doubles("/stats/substeps");
    // The squeeze film (docs/bodies.md, Coupling step 6): none while the gap is wide, some as
    // the box lands.
    const auto step_time = file.read_doubles("/stats/time");
    const auto film = file.read_doubles("/stats/squeeze_film_particles");
    double film_early = 0, film_most = 0;
    for (std::size_t r = 0; r < film.size(); ++r) {
      if (step_time[r] < 0.1) film_early = std::max(film_early, film[r]);
      film_most = std::max(film_most, film[r]);
    }
    double lowest = 1.0, speed = 0, balance = 0;
    int n = 0;
    for (std::size_t r = 0; r < box.time.size(); ++r) {
      lowest = std::min(lowest, box.position[3 * r + 1] - 0.5 * H);
      if (box.time[r] < box.time.back() - 0.2) continue;
      speed = std::max(speed, std::hypot(box.velocity[3 * r], box.velocity[3 * r + 1]));
      balance += box.force_contact[3 * r + 1] + box.force_fluid[3 * r + 1];
      ++n;
    }
    balance /= n;
    const double bottom = box.position[3 * (box.time.size() - 1) + 1] - 0.5 * H;
    std::printf(
        "d0 = %.3f m: lowest bottom %.2e m, final bottom %.2e m, speed %.1e m/s, "
        "(F_c + F_f) / M g - 1 = %+.2f %%, sub-steps in the last step %.0f, squeeze-film "
        "particles: %.0f before t = 0.1 s, at most %.0f\n",
        d0, lowest, bottom, speed, 100 * (balance / weight - 1), substeps.back(), film_early,
        film_most);
    EXPECT_GT(lowest, -0.01 * d0);
    EXPECT_LT(std::abs(bottom), 0.01 * d0);
    EXPECT_LT(speed, 5e-3);
    EXPECT_LT(std::abs(balance / weight - 1), 0.05);
    EXPECT_GT(substeps.back(), 1.0);
    EXPECT_EQ(film_early, 0.0);
    EXPECT_GT(film_most, 0.0);
  }
}

}  // namespace
}  // namespace washout
