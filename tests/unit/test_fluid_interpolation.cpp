// The linear moving-least-squares interpolation at a wall's mirror point
// (engine/core/fluid_interpolation.hpp): exact for a linear field where the fluid fills the
// support on one side of the point (the flat wall the mirror points are made for), and never an
// extrapolation that amplifies the fluid's values more than kMaxLinearAmplification, where the
// point lies beyond the few particles it is fitted to (the slot under a lifting gate, the tip of
// a flow). Without that bound the 3D wash-out's markers reached 10-33 m/s next to fluid moving
// at 1 m/s (docs/method.md, twelfth session).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/core/fluid_interpolation.hpp"
#include "engine/core/neighbor_grid.hpp"

namespace washout {
namespace {

constexpr double kD0 = 0.01;

double linear_field(const Vec3& x) { return 3.0 + 200.0 * x[0] - 500.0 * x[1]; }

struct Interpolated {
  double value = 0.0, amplification = 0.0, fraction = 0.0;
  double lowest = 1e300, highest = -1e300;  // of the fluid values that took part
};

Interpolated interpolate(const Particles& p, const Vec3& m) {
  const SphContext ctx(2, kD0, 1.2, 1000.0, PeriodicBox{});
  NeighborGrid grid;
  grid.build(p, 2.0 * ctx.h, PeriodicBox{});
  Interpolated out;
  const double at[3] = {m[0], m[1], m[2]};
  out.fraction = interpolate_fluid_linear(ctx, grid, p, at, [&](std::uint32_t f, double w) {
    const double v = linear_field(p.x(f));
    out.value += w * v;
    out.amplification += std::abs(w);
    out.lowest = std::min(out.lowest, v), out.highest = std::max(out.highest, v);
  });
  return out;
}

Particles fluid_at(const std::vector<Vec3>& points) {
  Particles p;
  p.dim = 2;
  for (const Vec3& x : points) p.add(ParticleKind::Fluid, x, Vec3::Zero(), -1);
  p.fluid_count = p.size();
  return p;
}

// Fluid on one side of a flat wall at y = 0 (the lattice's rows at (j + 1/2) d0); the mirror
// point of the first wall layer lies d0/2 above the wall, that of the third 2.5 d0 above it.
TEST(FluidInterpolation, ExactForALinearFieldBesideAFlatWall) {
  std::vector<Vec3> points;
  for (int j = 0; j < 8; ++j)
    for (int i = -10; i < 10; ++i) points.emplace_back((i + 0.5) * kD0, (j + 0.5) * kD0, 0.0);
  const Particles p = fluid_at(points);
  for (double height : {0.5, 1.5, 2.5}) {
    const Vec3 m(0.3 * kD0, height * kD0, 0.0);
    const Interpolated got = interpolate(p, m);
    std::printf("mirror point %.1f d0 from the wall: sum |w| = %.3f, error %.2e\n", height,
                got.amplification, got.value - linear_field(m));
    EXPECT_NEAR(got.value, linear_field(m), 1e-9);
    EXPECT_LE(got.amplification, kMaxLinearAmplification);
  }
}

// Four particles at the mouth of a slot and a point a spacing beyond and above them: the linear
// fit there has sum |w| = 4.0 (measured with the bound lifted) and would extrapolate the steep
// field; the interpolation keeps to the Shepard average, inside the range of the values it is
// made from.
TEST(FluidInterpolation, NoExtrapolationBeyondASparseNeighbourhood) {
  const Particles p = fluid_at({Vec3(0.0, 0.5 * kD0, 0.0), Vec3(-kD0, 0.5 * kD0, 0.0),
                                Vec3(-kD0, 1.5 * kD0, 0.0), Vec3(-2.0 * kD0, 0.5 * kD0, 0.0)});
  const Vec3 m(kD0, kD0, 0.0);
  const Interpolated got = interpolate(p, m);
  std::printf(
      "beyond a slot's mouth: fluid fraction %.3f, sum |w| = %.3f, value %.4f in [%.4f, "
      "%.4f]\n",
      got.fraction, got.amplification, got.value, got.lowest, got.highest);
  ASSERT_GE(got.fraction, kDryFluidFraction);  // wet enough to be interpolated at all
  EXPECT_LE(got.amplification, kMaxLinearAmplification);
  EXPECT_GE(got.value, got.lowest - 1e-12);
  EXPECT_LE(got.value, got.highest + 1e-12);
}

}  // namespace
}  // namespace washout
