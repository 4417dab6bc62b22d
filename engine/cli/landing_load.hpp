#pragma once
// Loads averaged over a physical time window, and the impulse of a landing (issue 15, "Bounded
// landing loads"; docs/stability.md "Landing loads"). A body that lands stops the water under
// and around it in one fluid step: the one-step load is that water's momentum over dt, so its
// peak grows as 1/dt and means nothing physical. Its impulse (the integral of the load over
// the landing) and its mean over a fixed window of time do not depend on dt, which is what the
// body report gives beside the raw one-step peak.
//
// A body series has one row per fluid step: row k holds the load applied during the step that
// ends at time[k], so the load is piecewise constant, row k acting on (time[k-1], time[k]].
#include <cstddef>
#include <vector>

namespace washout::cli {

// The step bounds of a series: b[0] = time[0] - (time[1] - time[0]) (the first step assumed as
// long as the second; 0 for a one-row series), b[k + 1] = time[k]. Empty for no rows.
std::vector<double> step_bounds(const std::vector<double>& time);

// The integral of a piecewise-constant load over [a, b] (clipped to the series), in N s:
// values[k * stride + component] is row k's load. bounds from step_bounds.
double load_integral(const std::vector<double>& bounds, const std::vector<double>& values,
                     std::size_t stride, std::size_t component, double a, double b);

struct WindowedPeak {
  double value = 0.0;  // the window mean of largest magnitude (signed), N
  double time = 0.0;   // the centre of that window, s
};

// The largest-magnitude mean of the load over any window of `window` seconds inside the series
// (the whole series' mean if it is shorter). Exact for a piecewise-constant load: the mean is
// linear between the positions where a window edge crosses a step bound, so those are the only
// candidates. An empty series gives {0, 0}.
WindowedPeak windowed_peak(const std::vector<double>& bounds, const std::vector<double>& values,
                           std::size_t stride, std::size_t component, double window);

// The first landing: the first row whose contact force magnitude exceeds `threshold` after the
// body has been free of contact (at or below threshold) for at least `hold` seconds, counting
// from the start of the series (a body released in the air or in water lands at its first
// contact; a girder on its pier lands after it has left it). rows() when it never lands.
std::size_t first_landing(const std::vector<double>& bounds,
                          const std::vector<double>& contact_magnitude, double threshold,
                          double hold);

}  // namespace washout::cli
