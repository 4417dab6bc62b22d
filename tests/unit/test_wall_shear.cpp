// The law of the wall behind wall_friction = "log_law" (engine/fluid/wall_shear.cpp): the
// friction velocity must satisfy the viscous sublayer u_t = u_* y+ below y+ = 11.06 and the
// log layer u_t / u_* = ln(y+) / 0.41 + 5.2 above it, continuous across the switch.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/fluid/isph_stages.hpp"

namespace washout {
namespace {

constexpr double kNu = 1e-6;

TEST(WallShear, ViscousSublayerIsLinear) {
  const double y = 1e-3, u_t = 1e-3;  // y+ = 1
  const double u_star = friction_velocity(u_t, y, kNu);
  std::printf("sublayer: u* = %.6e (expected %.6e)\n", u_star, std::sqrt(kNu * u_t / y));
  EXPECT_NEAR(u_star, std::sqrt(kNu * u_t / y), 1e-12);
}

TEST(WallShear, LogLayerSatisfiesTheLawOfTheWall) {
  // A dam-break surge: 2.4 m/s at d0/2 = 1.8 mm from the floor.
  for (const double y : {1.8e-3, 3.65e-3, 2.5e-3 * 2}) {
    const double u_t = 2.4;
    const double u_star = friction_velocity(u_t, y, kNu);
    const double y_plus = y * u_star / kNu;
    const double law = std::log(y_plus) / 0.41 + 5.2;
    std::printf("y = %.2e m: u* = %.4f m/s, y+ = %.0f, u_t/u* = %.4f, law %.4f\n", y, u_star,
                y_plus, u_t / u_star, law);
    EXPECT_GT(y_plus, 11.06);
    EXPECT_NEAR(u_t / u_star, law, 1e-6 * law);
  }
}

TEST(WallShear, ContinuousAcrossTheSublayerEdge) {
  // u_t at which y+ = 11.06 with the sublayer law: both branches must give the same u*.
  const double y = 1e-3, y_plus = 11.06;
  const double u_star = y_plus * kNu / y, u_t = u_star * y_plus;
  const double below = friction_velocity(u_t * (1 - 1e-9), y, kNu);
  const double above = friction_velocity(u_t * (1 + 1e-9), y, kNu);
  std::printf("edge: u* %.8e below, %.8e above\n", below, above);
  EXPECT_NEAR(below, above, 2e-3 * u_star);  // the laws meet at y+ = 11.06 to 0.1 %
}

TEST(WallShear, NoFlowNoStress) {
  EXPECT_EQ(friction_velocity(0.0, 1e-3, kNu), 0.0);
  EXPECT_EQ(friction_velocity(1.0, 0.0, kNu), 0.0);
}

}  // namespace
}  // namespace washout
