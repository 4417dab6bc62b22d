#pragma once
// What a scene's probes read each step (docs/scenes.md, "Probes"): the values an instrument at
// that place would give, from the fluid particles as the step left them.
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/particles.hpp"
#include "engine/core/sph_context.hpp"
#include "engine/model/model.hpp"

namespace washout {

// A pressure sensor: the Shepard average of the fluid's pressure within the support of its
// point, 0 where the point is dry. A sensor with a `facing` normal sees only the fluid in front
// of its face, (x_f - point) . facing >= 0: near a wall's edge the support also reaches the
// water running past the edge, which presses on other faces.
double sensor_pressure(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                       const ProbeSpec& probe);

// A wave gauge at probe.point (its vertical coordinate is the bed), reading as probe.gauge says:
// - Surface: the depth of the water standing on the bed, from the bed to the top of the fluid in
//   the column within d0 of the gauge across the flow, plus d0/2. The column is followed up from
//   the bed while the fluid in it is continuous: a gap of more than kGaugeAirGap particle
//   spacings is air, and a jet or spray above it is not water standing on the bed.
// - WettedLength: the length of the gauge's vertical line under water, the fluid fraction
//   integrated along it, sum_f V_f W(r_f) with W the kernel one dimension down and r_f the
//   particle's distance from the line (exact for a level layer; a jet crossing the line adds its
//   thickness). The line must stand 2h clear of walls across the flow.
// The highest particle over the column, the reading before, took a jet thrown over SPHERIC
// Test 2's box for 0.43 m of water where the wire gauge read 0.15 m (docs/method.md, thirty-ninth
// session).
double water_height(const SphContext& ctx, const Particles& p, int up, const ProbeSpec& probe);

// The spacing-normalised vertical gap in the gauge's column taken as air.
constexpr double kGaugeAirGap = 2.0;

// The front: the furthest fluid particle along probe.axis that is part of the bulk (summation
// density above half of rho0, so that lone spray does not count), plus d0/2.
double front_position(const SphContext& ctx, const Particles& p, double rho0,
                      const ProbeSpec& probe);

}  // namespace washout
