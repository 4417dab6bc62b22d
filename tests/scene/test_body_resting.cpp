// A heavy box resting on the floor of a water tank (scenes/sinking_box_2d.lua with drop = 0):
// fluid, contact and sub-stepping together. It must stay put on the contact springs, with the
// contact and fluid loads carrying its weight, at two resolutions.
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
//  - it stays: the bottom within d0/100 of the floor (the static overlap of the contact springs,
//    F_c / (N k_n), is about 3e-8 m), and after 0.05 s its speed stays below 1e-6 m/s. It starts
//    just touching and sinks onto its springs (up to g / omega ~ 4e-4 m/s, with a contact period
//    2 pi / omega ~ 0.3 ms, damped by eps = 0.5 within a few ms); after that only the fluid's
//    noise could move it, and it does not;
//  - F_c + F_f = M g within 1e-3 (at rest the momentum balance is exact up to the contact's
//    average over the step);
//  - the contact is sub-stepped: more than one sub-step per fluid step, every step.
// Without water under the box the fluid presses it down (F_f < 0): printed, not asserted.
TEST(BodyResting, HeavyBoxStaysOnTheFloorUnderWater) {
  const double B = 0.08, H = 0.04, rho_b = 2000.0, g = 9.81;
  const double weight = rho_b * B * H * g;
  for (double d0 : {0.01, 0.005}) {
    char name[64];
    std::snprintf(name, sizeof name, "body_resting_%g", d0);
    const cli::RunOutcome outcome =
        testing::run_scene("sinking_box_2d.lua", name,
                           {{"d0", std::to_string(d0)}, {"drop", "0"}, {"end_time", "0.3"}});
    io::RunFileReader file(outcome.h5_path);
    const testing::BodySeries box = testing::read_body_series(file, "box");
    const auto substeps = file.read_doubles("/stats/substeps");
    const std::size_t rows = box.position.size() / 3;
    double offset = 0, speed = 0, balance = 0;
    for (std::size_t r = 0; r < rows; ++r) {
      offset = std::max(offset, std::abs(box.position[3 * r + 1] - 0.5 * H));
      if (box.time[r] >= 0.05)
        speed = std::max(speed, std::hypot(box.velocity[3 * r], box.velocity[3 * r + 1]));
      balance = std::max(
          balance,
          std::abs(box.force_contact[3 * r + 1] + box.force_fluid[3 * r + 1] - weight) / weight);
    }
    const double fewest = *std::min_element(substeps.begin(), substeps.end());
    std::printf(
        "d0 = %.3f m: largest offset from the floor %.1e m, speed %.1e m/s, "
        "|F_c + F_f - M g| / M g = %.1e, F_f = %.2f N/m, F_c = %.2f N/m, "
        "sub-steps per step %.0f..%.0f\n",
        d0, offset, speed, balance, box.force_fluid[3 * rows - 2], box.force_contact[3 * rows - 2],
        fewest, *std::max_element(substeps.begin(), substeps.end()));
    EXPECT_LT(offset, 0.01 * d0);
    EXPECT_LT(speed, 1e-6);
    EXPECT_LT(balance, 1e-3);
    EXPECT_GT(fewest, 1.0);
  }
}

}  // namespace
}  // namespace washout
