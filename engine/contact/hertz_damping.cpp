#include "engine/contact/hertz_damping.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace washout::contact {
namespace {

double acceleration(double xi, double rate, double alpha) {
  const double x = std::max(xi, 0.0);
  return -x * std::sqrt(x) - alpha * std::sqrt(std::sqrt(x)) * rate;
}

}  // namespace

double hertz_restitution(double alpha) {
  // The undamped contact lasts 3.22 dimensionless time units; 2e-4 resolves it to ~1e-8 in eps.
  const double step = 2e-4;
  double xi = 0.0, rate = 1.0;
  for (int n = 0; n < 500000; ++n) {
    const double k1x = rate, k1v = acceleration(xi, rate, alpha);
    const double k2x = rate + 0.5 * step * k1v;
    const double k2v = acceleration(xi + 0.5 * step * k1x, k2x, alpha);
    const double k3x = rate + 0.5 * step * k2v;
    const double k3v = acceleration(xi + 0.5 * step * k2x, k3x, alpha);
    const double k4x = rate + step * k3v;
    const double k4v = acceleration(xi + step * k3x, k4x, alpha);
    const double next_xi = xi + step / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double next_rate = rate + step / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (next_xi <= 0.0 && n > 0) {
      // Past the end of contact: interpolate the rate at xi = 0 linearly in xi.
      const double f = xi / (xi - next_xi);
      return -(rate + f * (next_rate - rate));
    }
    if (next_rate >= 0.0 && rate < 0.0) return 0.0;  // came to rest inside: overdamped
    xi = next_xi;
    rate = next_rate;
  }
  return 0.0;
}

double hertz_damping_factor(double restitution) {
  if (!(restitution > 0.0) || !(restitution <= 1.0))
    throw std::invalid_argument("hertz_damping_factor: restitution must be in (0, 1]");
  if (restitution == 1.0) return 0.0;
  double low = 0.0, high = 1.0;
  while (hertz_restitution(high) > restitution) high *= 2.0;
  while (high - low > 1e-10 * high) {
    const double mid = 0.5 * (low + high);
    if (hertz_restitution(mid) > restitution)
      low = mid;
    else
      high = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace washout::contact
