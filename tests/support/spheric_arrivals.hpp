#pragma once
// When the water of SPHERIC Test 2 (scenes/validation/spheric_test2_3d.lua) reaches its gauges,
// in a run and in the experiment: the first time the level at H3 and H2 exceeds 2 cm and the
// pressure at P1, on the box's face, exceeds 0.2 rho g H (H = 0.55 m), between the two samples
// that cross it. Recomputed here from the probes, independently of the scene's `arrival` score;
// so is each gauge's agreement with the measured level (gauges_rms).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/scene_runner.hpp"

namespace washout::testing {

struct SphericArrival {
  const char* gauge;   // the probe, and the CSV's column prefix
  const char* column;  // the CSV's column
  double level;        // m or Pa
};

inline std::vector<SphericArrival> spheric_arrivals() {
  const double rho_g_H = 1000.0 * 9.81 * 0.55;
  return {{"H3", "H3_m", 0.02}, {"H2", "H2_m", 0.02}, {"P1", "P1_Pa", 0.2 * rho_g_H}};
}

// The first crossing of `level` after t = 0.01 s (the sensors' zero offsets are below every
// level); NaN when the series never crosses it.
inline double first_crossing(const std::vector<double>& t, const std::vector<double>& v,
                             double level) {
  for (std::size_t k = 1; k < t.size(); ++k)
    if (t[k] >= 0.01 && v[k] > level)
      return t[k - 1] + (t[k] - t[k - 1]) * (level - v[k - 1]) / (v[k] - v[k - 1]);
  return std::nan("");
}

// The experiment's arrivals, in spheric_arrivals()' order (the file read once).
inline std::vector<double> measured_arrivals() {
  const auto csv = read_csv(refdata("spheric_test2_kleefsman2005.csv"));
  std::vector<double> t;
  for (const auto& cell : csv.at("t_s")) t.push_back(std::stod(cell));
  std::vector<double> arrivals;
  for (const auto& a : spheric_arrivals()) {
    std::vector<double> v;
    for (const auto& cell : csv.at(a.column)) v.push_back(std::stod(cell));
    arrivals.push_back(first_crossing(t, v, a.level));
  }
  return arrivals;
}

inline double run_arrival(io::RunFileReader& run, const SphericArrival& a) {
  const std::string probe = std::string("/probes/") + a.gauge;
  return first_crossing(run.read_doubles(probe + "/time"), run.read_doubles(probe + "/value"),
                        a.level);
}

// RMS of (h_run - h_measured) / H at H1-H4 (in that order) over the experiment's samples up to
// t_end, the run's level interpolated linearly at the experiment's times (H = 0.55 m; the file
// read once for the four).
inline std::vector<double> gauges_rms(io::RunFileReader& run, double t_end) {
  const auto csv = read_csv(refdata("spheric_test2_kleefsman2005.csv"));
  std::vector<double> t_seen;
  for (const auto& cell : csv.at("t_s")) t_seen.push_back(std::stod(cell));
  std::vector<double> result;
  for (const char* gauge : {"H1", "H2", "H3", "H4"}) {
    const std::string probe = std::string("/probes/") + gauge;
    const auto t_run = run.read_doubles(probe + "/time");
    const auto h_run = run.read_doubles(probe + "/value");
    const auto& h_cells = csv.at(std::string(gauge) + "_m");
    double sum2 = 0.0;
    std::size_t count = 0, r = 1;
    for (std::size_t k = 0; k < t_seen.size(); ++k) {
      const double t = t_seen[k];
      if (t > t_end || t > t_run.back()) break;
      while (r + 1 < t_run.size() && t_run[r] < t) ++r;
      const double w = (t - t_run[r - 1]) / (t_run[r] - t_run[r - 1]);
      const double h = h_run[r - 1] + std::clamp(w, 0.0, 1.0) * (h_run[r] - h_run[r - 1]);
      sum2 += std::pow((h - std::stod(h_cells[k])) / 0.55, 2);
      ++count;
    }
    result.push_back(count ? std::sqrt(sum2 / count) : std::nan(""));
  }
  return result;
}

}  // namespace washout::testing
