#pragma once
// The draft of the floating box of scenes/floating_box_{2d,3d}.lua at each row of /bodies/box:
// the mean of the water-height probes (read once, interpolated to the row's time) less the
// box's bottom, X_up - half_height. Shared by the short and the long floating-box tests.
#include <string>
#include <vector>

#include "support/scene_runner.hpp"

namespace washout::testing {

inline std::vector<double> box_draft(const io::RunFileReader& file,
                                     const std::vector<std::string>& probes, int up,
                                     double half_height) {
  const auto time = file.read_doubles("/bodies/box/time");
  const auto position = file.read_doubles("/bodies/box/position");
  std::vector<std::vector<double>> probe_time, probe_value;
  for (const auto& name : probes) {
    probe_time.push_back(file.read_doubles("/probes/" + name + "/time"));
    probe_value.push_back(file.read_doubles("/probes/" + name + "/value"));
  }
  std::vector<double> draft(time.size());
  for (std::size_t r = 0; r < time.size(); ++r) {
    double level = 0;
    for (std::size_t k = 0; k < probes.size(); ++k)
      level += interpolate(probe_time[k], probe_value[k], time[r]);
    level /= static_cast<double>(probes.size());
    draft[r] = level - (position[3 * r + up] - half_height);
  }
  return draft;
}

// The mean of a series over its rows with t >= from (the settled draft over a last window).
inline double mean_since(const std::vector<double>& time, const std::vector<double>& values,
                         double from) {
  double sum = 0;
  int rows = 0;
  for (std::size_t r = 0; r < time.size(); ++r)
    if (time[r] >= from) sum += values[r], ++rows;
  return sum / rows;
}

}  // namespace washout::testing
