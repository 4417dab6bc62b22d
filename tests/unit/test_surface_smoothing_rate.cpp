// The surface velocity smoothing as a rate (surface_smoothing.cpp, surface_smoothing_courant >
// 0): the fraction set for a step of the reference Courant number is compounded for the step
// taken, so that a run does not depend on its step (docs/method.md, twelfth session). Taken
// every step instead (the default, reference 0), halving dt_max doubles the smoothing per
// second: the 2D a/20 front moves by 0.03 a.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/fluid/isph_stages.hpp"

namespace washout {
namespace {

constexpr double kReference = 0.2;

TEST(SurfaceSmoothingRate, AStepOfTheReferenceCourantTakesTheFractionSet) {
  for (double s : {0.1, 0.5, 0.9})
    EXPECT_NEAR(surface_smoothing_for_step(s, kReference, kReference), s, 1e-15);
}

// What stays unsmoothed multiplies over steps: k steps of C / k leave (1 - f(C / k))^k, which
// must be what one step of C leaves. A per-step fraction would leave (1 - s)^k instead.
TEST(SurfaceSmoothingRate, ManySmallStepsSmoothAsOneLargeStep) {
  const double s = 0.5;
  for (double courant : {0.05, 0.2, 0.7}) {
    const double one = 1.0 - surface_smoothing_for_step(s, courant, kReference);
    for (int k : {2, 4, 10}) {
      const double many = std::pow(1.0 - surface_smoothing_for_step(s, courant / k, kReference), k);
      EXPECT_NEAR(many, one, 1e-12) << "C = " << courant << ", k = " << k;
    }
  }
}

TEST(SurfaceSmoothingRate, GrowsWithTheStepAndStaysAFraction) {
  double previous = 0.0;
  for (double courant : {0.01, 0.1, 0.2, 0.4, 1.0, 10.0}) {
    const double f = surface_smoothing_for_step(0.5, courant, kReference);
    EXPECT_GT(f, previous);
    EXPECT_LT(f, 1.0);
    previous = f;
  }
  EXPECT_EQ(surface_smoothing_for_step(0.5, 0.0, kReference), 0.0);  // no motion, nothing to do
  EXPECT_EQ(surface_smoothing_for_step(0.0, 0.3, kReference), 0.0);  // off stays off
  EXPECT_EQ(surface_smoothing_for_step(1.0, 0.3, kReference), 1.0);  // full stays full
}

TEST(SurfaceSmoothingRate, WithoutAReferenceTheFractionIsTakenEveryStep) {
  for (double courant : {0.0, 0.05, 0.2, 1.0})
    EXPECT_EQ(surface_smoothing_for_step(0.5, courant, 0.0), 0.5);
}

}  // namespace
}  // namespace washout
