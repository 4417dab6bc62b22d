// What the probes read (engine/sim/probes.hpp), against the geometry of water laid on a
// lattice: a wave gauge over a level layer with a jet above it, and a pressure sensor on a
// plate with different water on each side.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/neighbor_grid.hpp"
#include "engine/sim/probes.hpp"

namespace washout {
namespace {

constexpr double kD0 = 0.01;

// Lattice fluid filling [x0, x1] along x, the width `across` (3D: along y, from 0) and
// [z0, z1] vertically (y in 2D), every particle at `pressure`.
void add_block(Particles& p, double x0, double x1, double across, double z0, double z1,
               double pressure) {
  const int up = p.dim - 1;
  const int nx = static_cast<int>(std::lround((x1 - x0) / kD0));
  const int ny = p.dim == 3 ? static_cast<int>(std::lround(across / kD0)) : 1;
  const int nz = static_cast<int>(std::lround((z1 - z0) / kD0));
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        Vec3 x = Vec3::Zero();
        x[0] = x0 + (i + 0.5) * kD0;
        if (p.dim == 3) x[1] = (j + 0.5) * kD0;
        x[up] = z0 + (k + 0.5) * kD0;
        p.add(ParticleKind::Fluid, x, Vec3::Zero(), -1);
        p.pressure.back() = pressure;
      }
}

ProbeSpec gauge_at_middle(int dim, ProbeSpec::Gauge reads) {
  ProbeSpec probe;
  probe.quantity = ProbeSpec::Quantity::WaterHeight;
  probe.gauge = reads;
  probe.point = Vec3(0.2, dim == 3 ? 0.2 : 0.0, 0.0);  // the bed at 0
  return probe;
}

// What a pressure sensor at `point` facing `facing` (zero: no facing) reads from the fluid p.
double sensor_reading(const SphContext& ctx, const Particles& p, const Vec3& point,
                      const Vec3& facing) {
  NeighborGrid grid;
  grid.build(p, 2.0 * ctx.h, ctx.periodic);
  ProbeSpec sensor;
  sensor.quantity = ProbeSpec::Quantity::Pressure;
  sensor.point = point;
  sensor.facing = facing;
  return sensor_pressure(ctx, grid, p, sensor);
}

// A level layer 0.10 m deep over a bed 0.4 m wide, and a jet 0.03 m thick crossing above it
// with 0.05 m of air between. The surface gauge reads the layer; the wire gauge its wetted
// length, the layer and the jet; the highest particle (the reading before) would be 0.18 m.
TEST(WaveGauge, ReadsTheWaterStandingOnTheBedOrTheWireUnderWater) {
  for (int dim : {2, 3}) {
    const SphContext ctx(dim, kD0, 1.3, 1000.0, PeriodicBox{});
    Particles p;
    p.dim = dim;
    add_block(p, 0.0, 0.4, 0.4, 0.0, 0.10, 0.0);
    add_block(p, 0.1, 0.3, 0.4, 0.15, 0.18, 0.0);
    const int up = dim - 1;
    const double surface =
        water_height(ctx, p, up, gauge_at_middle(dim, ProbeSpec::Gauge::Surface));
    const double wetted =
        water_height(ctx, p, up, gauge_at_middle(dim, ProbeSpec::Gauge::WettedLength));
    std::printf("dim %d: surface %.6f m (layer 0.10), wetted length %.6f m (layer + jet 0.13)\n",
                dim, surface, wetted);
    // The top particle's centre is d0/2 under the layer's top: the reading adds it back.
    EXPECT_NEAR(surface, 0.10, 1e-12);
    // The wetted length is the kernel's sum across the line, exact up to the cubic spline's
    // partition of unity on the lattice at h = 1.3 d0 (well under 1 %).
    EXPECT_NEAR(wetted, 0.13, 0.01 * 0.13);

    // Only the jet over a dry bed: no water stands on the bed; the wire is wet over the jet.
    Particles jet;
    jet.dim = dim;
    add_block(jet, 0.1, 0.3, 0.4, 0.15, 0.18, 0.0);
    EXPECT_EQ(water_height(ctx, jet, up, gauge_at_middle(dim, ProbeSpec::Gauge::Surface)), 0.0);
    EXPECT_NEAR(water_height(ctx, jet, up, gauge_at_middle(dim, ProbeSpec::Gauge::WettedLength)),
                0.03, 0.01 * 0.03);
  }
}

// A thin plate at x = 0.2 with water at 100 Pa on its left and 300 Pa on its right: a sensor
// facing +x reads the right side's pressure, facing -x the left side's; without a facing it
// averages both sides.
TEST(PressureSensor, SeesTheFluidInFrontOfItsFaceOnly) {
  for (int dim : {2, 3}) {
    const SphContext ctx(dim, kD0, 1.3, 1000.0, PeriodicBox{});
    Particles p;
    p.dim = dim;
    add_block(p, 0.0, 0.2, 0.4, 0.0, 0.2, 100.0);
    add_block(p, 0.2, 0.4, 0.4, 0.0, 0.2, 300.0);
    const Vec3 plate(0.2, dim == 3 ? 0.2 : 0.1, dim == 3 ? 0.1 : 0.0);
    const double both = sensor_reading(ctx, p, plate, Vec3::Zero());
    const double right = sensor_reading(ctx, p, plate, Vec3::UnitX());
    const double left = sensor_reading(ctx, p, plate, -Vec3::UnitX());
    std::printf("dim %d: facing +x %.3f Pa, -x %.3f Pa, no facing %.3f Pa\n", dim, right, left,
                both);
    EXPECT_NEAR(right, 300.0, 1e-9);
    EXPECT_NEAR(left, 100.0, 1e-9);
    EXPECT_NEAR(both, 200.0, 1e-9);  // the lattice is symmetric about the plate
  }
}

// The same plate where a periodic channel's seam is: x periodic over [0, 0.4], the sensor at
// x = 0 facing +x. The water just beyond the seam (x near 0.4, 100 Pa) is behind its face: the
// side is taken across the seam as the distance is, so it reads the 300 Pa in front only.
TEST(PressureSensor, JudgesItsSideAcrossAPeriodicSeam) {
  for (int dim : {2, 3}) {
    PeriodicBox box;
    box.periodic[0] = true;
    box.length[0] = 0.4;
    const SphContext ctx(dim, kD0, 1.3, 1000.0, box);
    Particles p;
    p.dim = dim;
    add_block(p, 0.0, 0.2, 0.4, 0.0, 0.2, 300.0);
    add_block(p, 0.2, 0.4, 0.4, 0.0, 0.2, 100.0);
    const Vec3 seam(0.0, dim == 3 ? 0.2 : 0.1, dim == 3 ? 0.1 : 0.0);
    const double ahead = sensor_reading(ctx, p, seam, Vec3::UnitX());
    const double behind = sensor_reading(ctx, p, seam, -Vec3::UnitX());
    std::printf("dim %d, at the seam: facing +x %.3f Pa, -x %.3f Pa\n", dim, ahead, behind);
    EXPECT_NEAR(ahead, 300.0, 1e-9);
    EXPECT_NEAR(behind, 100.0, 1e-9);
  }
}

}  // namespace
}  // namespace washout
