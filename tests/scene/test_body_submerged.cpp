// A fixed body held under still water (scenes/submerged_body_2d.lua): the pressure integrated
// over its surface, F_f = sum -P n dS, equals the buoyancy rho0 g V (Archimedes), with no
// horizontal force and no torque, for a box and a disc at two resolutions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

struct Load {
  double vertical = 0, horizontal = 0, torque = 0;  // time averages
};

// The loads averaged from `from` to the run's end.
Load run_submerged(const std::string& shape, double d0, double end_time, double from) {
  char name[64];
  std::snprintf(name, sizeof name, "submerged_%s_%g", shape.c_str(), d0);
  const cli::RunOutcome outcome = testing::run_scene("submerged_body_2d.lua", name,
                                                     {{"shape", shape},
                                                      {"d0", std::to_string(d0)},
                                                      {"end_time", std::to_string(end_time)},
                                                      {"output_interval", "0.5"}});
  io::RunFileReader file(outcome.h5_path);
  const auto time = file.read_doubles("/bodies/body/time");
  const auto force = file.read_doubles("/bodies/body/force_fluid");
  const auto torque = file.read_doubles("/bodies/body/torque_fluid");
  Load load;
  int n = 0;
  for (std::size_t r = 0; r < time.size(); ++r) {
    if (time[r] < from) continue;
    load.horizontal += force[3 * r];
    load.vertical += force[3 * r + 1];
    load.torque += torque[3 * r + 2];
    ++n;
  }
  load.vertical /= n;
  load.horizontal /= n;
  load.torque /= n;
  return load;
}

// The box stays on the lattice it starts from (its faces are lattice planes): 0.3 s, averaged
// after the first 0.05 s, the start-up of the fluid's discrete hydrostatic equilibrium. The disc
// is cut out of the lattice: the fluid around it rearranges over the first second (its load
// swings by 5-9 % meanwhile) and settles disordered, so it runs 2 s, averaged over the second.
// Bounds on |F_f / (rho0 g V) - 1|: at d0 = 0.01 m 2 % for the box and 3 % for the disc, only 5
// particles in radius (its wall treatment, mirror points across a surface curved on the
// kernel's scale, 2h = R/2, is first order in h/R); 1 % for both at d0 = 0.005 m. The error must
// also shrink from the coarse to the fine resolution, unless both lie within 0.3 %, the surface
// quadrature's own error (test_body_builder.cpp), where their order is noise.
// Measured: box -0.59 % and -0.15 %; disc +1.9 % and +0.6 % with the pressure gradient
// normalised by each particle's neighbours. With the lattice normalisation alone the settled
// disc's load falls to -1.8 % and -2.5 % by 3 s (the water's pressure settles low in a
// disordered arrangement, docs/method.md, seventeenth session), after +1.0 % and 0.0 % over the
// first 0.3 s, the window this test took before.
// The horizontal force and the torque vanish by symmetry: bound 0.1 % of rho0 g V (times the
// size for the torque) for the box, far above rounding and far below any asymmetric pressure
// error; 0.5 % for the disc, whose settled disordered water is symmetric on average only (its
// vertical load still swings by 0.3-0.5 % of rho0 g V, standard deviation; F_x measured -0.3 %).
TEST(BodySubmerged, PressureForceEqualsBuoyancyAtTwoResolutions) {
  const double rho_g = 1000.0 * 9.81, size = 0.1;
  for (const std::string shape : {"box", "disc"}) {
    const double volume = shape == "box" ? size * size : std::numbers::pi * 0.25 * size * size;
    const double buoyancy = rho_g * volume;
    double previous = 1.0;
    const bool disc = shape == "disc";
    for (const auto& [d0, bound] : {std::pair{0.01, disc ? 0.03 : 0.02}, std::pair{0.005, 0.01}}) {
      const Load load =
          disc ? run_submerged(shape, d0, 2.0, 1.0) : run_submerged(shape, d0, 0.3, 0.05);
      const double error = load.vertical / buoyancy - 1.0;
      std::printf(
          "%s, d0 = %.3f m: F_f = %.3f N/m against rho0 g V = %.3f N/m: error %+.2f %%, "
          "F_x / rho0 g V = %.1e, M / (rho0 g V size) = %.1e\n",
          shape.c_str(), d0, load.vertical, buoyancy, 100 * error, load.horizontal / buoyancy,
          load.torque / (buoyancy * size));
      EXPECT_LT(std::abs(error), bound) << shape << " at d0 = " << d0;
      constexpr double quadrature = 0.003;
      EXPECT_LT(std::abs(error), std::max(std::abs(previous), quadrature))
          << shape << ": no convergence";
      const double symmetry = disc ? 5e-3 : 1e-3;
      EXPECT_LT(std::abs(load.horizontal) / buoyancy, symmetry);
      EXPECT_LT(std::abs(load.torque) / (buoyancy * size), symmetry);
      previous = error;
    }
  }
}

}  // namespace
}  // namespace washout
