#pragma once
// Damping for the optional Hertz law F_n = k_n delta^{3/2} + alpha sqrt(m k_n) delta^{1/4}
// d(delta)/dt (Tsuji, Tanaka & Ishida 1992). With this form the restitution depends on alpha
// only (not on the impact speed), but there is no closed formula: it is found by integrating
// the dimensionless contact once, xi'' = -xi^{3/2} - alpha xi^{1/4} xi', xi(0) = 0, xi'(0) = 1.
namespace washout::contact {

// Restitution -xi'(end) of one dimensionless Hertz-Tsuji contact (RK4); 0 if it never ends.
double hertz_restitution(double alpha);

// The alpha that gives restitution eps (bisection on hertz_restitution, to 1e-10).
double hertz_damping_factor(double restitution);

}  // namespace washout::contact
