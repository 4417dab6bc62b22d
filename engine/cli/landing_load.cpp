#include "engine/cli/landing_load.hpp"

#include <algorithm>
#include <cmath>

namespace washout::cli {
namespace {

// I[j] = the integral of the load from bounds[0] to bounds[j].
std::vector<double> cumulative(const std::vector<double>& bounds, const std::vector<double>& values,
                               std::size_t stride, std::size_t component) {
  std::vector<double> integral(bounds.size(), 0.0);
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k)
    integral[k + 1] = integral[k] + values[k * stride + component] * (bounds[k + 1] - bounds[k]);
  return integral;
}

// The cumulative integral at time t (piecewise linear between bounds, clipped at the ends).
double integral_at(const std::vector<double>& bounds, const std::vector<double>& integral,
                   double t) {
  if (t <= bounds.front()) return 0.0;
  if (t >= bounds.back()) return integral.back();
  const std::size_t j = std::upper_bound(bounds.begin(), bounds.end(), t) - bounds.begin();
  const double span = bounds[j] - bounds[j - 1];
  const double f = span > 0 ? (t - bounds[j - 1]) / span : 1.0;
  return integral[j - 1] + f * (integral[j] - integral[j - 1]);
}

}  // namespace

std::vector<double> step_bounds(const std::vector<double>& time) {
  if (time.empty()) return {};
  std::vector<double> b(time.size() + 1);
  const double first_step = time.size() > 1 ? time[1] - time[0] : 0.0;
  b[0] = time[0] - first_step;
  std::copy(time.begin(), time.end(), b.begin() + 1);
  return b;
}

double load_integral(const std::vector<double>& bounds, const std::vector<double>& values,
                     std::size_t stride, std::size_t component, double a, double b) {
  if (bounds.size() < 2) return 0.0;
  const std::vector<double> integral = cumulative(bounds, values, stride, component);
  return integral_at(bounds, integral, b) - integral_at(bounds, integral, a);
}

WindowedPeak windowed_peak(const std::vector<double>& bounds, const std::vector<double>& values,
                           std::size_t stride, std::size_t component, double window) {
  WindowedPeak peak;
  if (bounds.size() < 2) return peak;
  const std::vector<double> integral = cumulative(bounds, values, stride, component);
  const double start = bounds.front(), end = bounds.back();
  if (!(window > 0) || end - start <= window) {  // shorter than the window: its mean
    peak.value = end > start ? integral.back() / (end - start) : values[component];
    peak.time = 0.5 * (start + end);
    return peak;
  }
  const double last_start = end - window;
  const auto consider = [&](double s) {
    s = std::clamp(s, start, last_start);
    const double mean =
        (integral_at(bounds, integral, s + window) - integral_at(bounds, integral, s)) / window;
    if (std::abs(mean) > std::abs(peak.value)) peak = {mean, s + 0.5 * window};
  };
  for (double b : bounds) {
    consider(b);           // the window's start on a bound
    consider(b - window);  // its end on a bound
  }
  return peak;
}

std::size_t first_landing(const std::vector<double>& bounds,
                          const std::vector<double>& contact_magnitude, double threshold,
                          double hold) {
  const std::size_t n = contact_magnitude.size();
  double free_since = bounds.empty() ? 0.0 : bounds.front();  // start of the current free stretch
  bool free = true;
  for (std::size_t k = 0; k < n; ++k) {
    if (contact_magnitude[k] > threshold) {
      if (free && bounds[k] - free_since >= hold) return k;
      free = false;
    } else if (!free) {
      free = true;
      free_since = bounds[k];
    }
  }
  return n;
}

}  // namespace washout::cli
