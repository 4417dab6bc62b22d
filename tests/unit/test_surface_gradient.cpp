// The corrector's gradient at free-surface particles (corrector.cpp). A block of still water,
// periodic along x, whose top row is the free surface; the surface itself (P = 0) lies d0/2
// above that row, as the PPE's ghost form puts it. Both surface forms must be exact for the
// hydrostatic field, which is linear and vanishes there; only the ghost-completed form sees the
// surface when the pressure does not vanish there (a level P0 throughout): it pushes the top
// row out, as a pressure above the air's must.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/core/neighbor_grid.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {
namespace {

constexpr int kColumns = 12, kRows = 8;
constexpr double kD0 = 0.01, kRho = 1000.0, kG = 9.81, kDt = 1e-3;

struct StillBlock {
  SphContext ctx;
  Particles p;
  NeighborList list;
  FluidWork work;
  StillBlock() : ctx(2, kD0, 1.2, kRho, periodic_x()) {
    p.dim = 2;
    for (int j = 0; j < kRows; ++j)
      for (int i = 0; i < kColumns; ++i)
        p.add(ParticleKind::Fluid, Vec3((i + 0.5) * kD0, (j + 0.5) * kD0, 0), Vec3::Zero(), -1);
    NeighborGrid grid;
    grid.build(p, 2 * ctx.h, ctx.periodic);
    grid.build_list(p, p.size(), 2 * ctx.h, list);
    for (int a = 0; a < 3; ++a) work.u_star[a].assign(p.size(), 0.0);
    work.free_surface.assign(p.size(), 0);
    work.unknown.assign(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.density[i] = kRho;
      work.unknown[i] = static_cast<std::int32_t>(i);
      if (is_top(i)) work.free_surface[i] = FluidWork::kSurface;
    }
  }
  static PeriodicBox periodic_x() {
    PeriodicBox box;
    box.periodic[0] = true;
    box.length[0] = kColumns * kD0;
    return box;
  }
  bool is_top(std::size_t i) const { return p.position[1][i] > (kRows - 1) * kD0; }
  // Velocities after the corrector from u* = 0: -(dt / rho) <grad P>.
  void correct(bool ghost) {
    GradientForms forms;
    forms.ghost_surface = ghost;
    correct_velocity(ctx, list, p, work, WallConditions::none(), Vec3(0, -kG, 0), kDt, forms);
  }
};

TEST(SurfaceGradient, BothFormsAreExactForHydrostaticsBelowTheSurface) {
  for (const bool ghost : {true, false}) {
    StillBlock b;
    const double surface = kRows * kD0;  // d0/2 above the top row
    for (std::size_t i = 0; i < b.p.size(); ++i)
      b.p.pressure[i] = kRho * kG * (surface - b.p.position[1][i]);
    b.correct(ghost);
    double worst = 0.0;
    for (std::size_t i = 0; i < b.p.size(); ++i) {
      if (!b.is_top(i)) continue;
      // grad P = -rho g y: the corrector gives u = +g dt y, what holds the row against gravity.
      worst = std::max(worst, std::abs(b.p.velocity[1][i] - kG * kDt) / (kG * kDt));
      worst = std::max(worst, std::abs(b.p.velocity[0][i]) / (kG * kDt));
    }
    std::printf("%s: largest relative error of the top row's correction %.2e\n",
                ghost ? "ghost" : "corrected", worst);
    EXPECT_LT(worst, 1e-10);
  }
}

TEST(SurfaceGradient, OnlyTheGhostFormSeesThePressureAboveTheAirs) {
  const double level = 100.0;  // Pa everywhere: the top row is P0 above the surface's P = 0
  for (const bool ghost : {true, false}) {
    StillBlock b;
    for (std::size_t i = 0; i < b.p.size(); ++i) b.p.pressure[i] = level;
    b.correct(ghost);
    // The drop from P0 to 0 over d0/2 is -2 P0 / d0 along y. The ghosts stand for the rows
    // above the top one, the mirror image of the rows below it, so they carry exactly half of
    // the support's y y moment: the ghost share is half the drop's gradient.
    const double full = kDt / kRho * 2.0 * level / kD0;
    for (std::size_t i = 0; i < b.p.size(); ++i) {
      if (!b.is_top(i)) continue;
      const double uy = b.p.velocity[1][i];
      if (ghost)
        EXPECT_NEAR(uy, 0.5 * full, 1e-12 * full) << "particle " << i;
      else
        EXPECT_LT(std::abs(uy), 1e-12 * full) << "particle " << i;
      EXPECT_LT(std::abs(b.p.velocity[0][i]), 1e-12 * full) << "particle " << i;
    }
    const std::size_t top = b.p.size() - 1;
    std::printf("%s: top row pushed out at %.4f of the full drop's correction\n",
                ghost ? "ghost" : "corrected", b.p.velocity[1][top] / full);
  }
}

}  // namespace
}  // namespace washout
