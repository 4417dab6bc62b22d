#pragma once
// The density-invariance term's relaxation for one step (docs/method.md, "The thirty-fourth
// session: alpha per unit time").
// The PPE's alpha (rho0 - <rho>_i) / dt^2 removes the fraction alpha of a particle's density error
// in one step: a rate alpha / dt in time. At a tenth of the step it corrects ten times faster, and
// the part of the error a shorter step does not make smaller (the summation density's noise over
// a disordered support, the strain accumulated near the surface) becomes a velocity alpha e / dt,
// ten times larger too: the small-step runs of the stability sweep gained energy and still water
// churned (docs/stability.md, docs/method.md). Relaxing at the rate of the reference step instead,
//   alpha_step = alpha min(1, dt / dt_reference),
// keeps the rate alpha / dt_reference in time at any shorter step. A longer step keeps alpha: it
// is a fraction of the error, at most 1.
namespace washout {

inline double density_relaxation_per_time(double alpha, double dt, double dt_reference) {
  if (!(dt_reference > 0) || dt >= dt_reference) return alpha;
  return alpha * (dt / dt_reference);
}

}  // namespace washout
