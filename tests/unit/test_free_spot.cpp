// Where a particle caught in a solid or put back onto another goes (engine/sim/free_spot.hpp),
// against made-up surroundings: which places count as free is given, the search's answer is
// checked against the nearest one of each kind.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/sim/free_spot.hpp"

namespace washout {
namespace {

constexpr double kD0 = 0.01;

// The search's points lie on spheres (circles in 2D) of radius k d0/2 about x: the first
// accepted one is on the smallest sphere that has one.
TEST(FreeSpot, IsTheNearestAcceptedPoint) {
  for (int dim : {2, 3}) {
    const Vec3 x(0.1, 0.2, dim == 3 ? 0.3 : 0.0);
    const auto spot = find_free_spot(x, dim, kD0, 40, [&](const Vec3& y) {
      return (y - x).norm() > 1.2 * kD0;  // nothing free closer than 1.2 d0
    });
    ASSERT_TRUE(spot.has_value());
    std::printf("dim %d: free spot at %.4f d0\n", dim, (*spot - x).norm() / kD0);
    EXPECT_NEAR((*spot - x).norm(), 1.5 * kD0, 1e-12);  // the third sphere, k = 3
    if (dim == 2) {
      EXPECT_EQ(spot->z(), 0.0);
    }
  }
  const Vec3 x = Vec3::Zero();
  EXPECT_FALSE(find_free_spot(x, 3, kD0, 40, [](const Vec3&) { return false; }).has_value());
}

// A particle by a wall's foot under deep water: holes (no particle within d0/2) from one
// spacing away (0.9 d0), room for one more only at the free surface 13 d0 above it. Put back onto
// another particle, it takes a hole next to it; caught in a closing gap, the room above.
TEST(FreePlace, APutBackParticleTakesAHoleNextToItAndAGapsParticleTheRoomFarAway) {
  for (int dim : {2, 3}) {
    const int up = dim - 1;
    const Vec3 x(0.5, dim == 3 ? 0.5 : 0.005, dim == 3 ? 0.005 : 0.0);
    const double surface = x[up] + 13.0 * kD0;
    FreePlaceTests tests;
    tests.clear_of_solids = [&](const Vec3& y) { return y[up] >= 0.005; };  // the floor at 0
    tests.hole = [&](const Vec3& y) {
      return tests.clear_of_solids(y) && (y - x).norm() >= 0.9 * kD0;
    };
    tests.with_room = [&](const Vec3& y) { return tests.hole(y) && y[up] >= surface; };

    const auto nearby = find_free_place(x, dim, kD0, tests, /*nearby_first=*/true);
    const auto wide = find_free_place(x, dim, kD0, tests, /*nearby_first=*/false);
    ASSERT_TRUE(nearby.has_value());
    ASSERT_TRUE(wide.has_value());
    std::printf("dim %d: put back onto another -> %.2f d0 away; out of a gap -> %.2f d0 away\n",
                dim, (*nearby - x).norm() / kD0, (*wide - x).norm() / kD0);
    EXPECT_NEAR((*nearby - x).norm(), 1.0 * kD0, 1e-12);  // the nearest hole, sphere k = 2
    EXPECT_TRUE(tests.with_room(*wide));
    EXPECT_GE((*wide - x).norm(), 12.99 * kD0);

    // No hole within 4 d0 (kNearbyRings spheres of d0/2): the wide search, room first.
    tests.hole = [&](const Vec3& y) {
      return tests.clear_of_solids(y) && (y - x).norm() >= 4.9 * kD0;
    };
    // Each point of the inner spheres is asked for room once: the wide search starts past them.
    const auto room = tests.with_room;
    int inner_room_tests = 0;
    tests.with_room = [&](const Vec3& y) {
      inner_room_tests += (y - x).norm() < (0.5 * kNearbyRings + 0.01) * kD0;
      return room(y);
    };
    const auto beyond = find_free_place(x, dim, kD0, tests, /*nearby_first=*/true);
    ASSERT_TRUE(beyond.has_value());
    EXPECT_TRUE(room(*beyond));
    int inner_points = 0;
    for (int k = 1; k <= kNearbyRings; ++k)
      inner_points += static_cast<int>(dim == 2 ? std::ceil(2.0 * std::numbers::pi * k)
                                                : std::ceil(4.0 * std::numbers::pi * k * k));
    std::printf("dim %d: %d room tests within 4 d0 for %d points there\n", dim, inner_room_tests,
                inner_points);
    EXPECT_EQ(inner_room_tests, inner_points);
  }
}

}  // namespace
}  // namespace washout
