#pragma once
// The rows of a `washout study` (one per combination of --vary values), written as study.csv,
// and the observed convergence order of the error in d0 (docs/validation.md).
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace washout::cli {

struct StudyRow {
  std::vector<std::string> values;  // one per varied parameter, as given on the command line
  std::string status = "not run";   // ok, unstable, bad input, output failed, crashed (...)
  int exit_code = -1;
  double particles = 0, fluid_particles = 0, steps = 0;
  std::vector<double> wall_seconds;  // one per repeat: the whole child run, setup included
  double peak_rss_bytes = 0;
  double ppe_iterations_per_step = std::numeric_limits<double>::quiet_NaN();
  // The run's threads and the cores other processes kept busy beside it (run_scoring.hpp):
  // a row whose threads waited for cores has a wall time that is not the machine's.
  double threads = std::numeric_limits<double>::quiet_NaN();
  double cores = std::numeric_limits<double>::quiet_NaN();
  double cores_busy_elsewhere = std::numeric_limits<double>::quiet_NaN();
  bool waited_for_cores() const;
  // Scores in the scene's order; the first is the primary `error`.
  std::vector<std::pair<std::string, double>> errors, bounds;
  std::string error_metric;
  double wall_min() const;
  double wall_median() const;
};

struct StudyTable {
  std::vector<std::string> names;  // varied parameters
  std::vector<StudyRow> rows;
  // The score names seen in any row, primary first.
  std::vector<std::string> score_names() const;
  // Writes CSV with one header line; NaN and missing numbers are empty cells.
  bool write_csv(const std::string& path) const;
};

// log(error) = p log(d0) + c fitted over the completed rows with a finite, positive error.
struct ConvergenceFit {
  std::string score;
  std::string group;  // the other varied values, "" when only d0 varies
  int points = 0;
  double order = std::numeric_limits<double>::quiet_NaN();
  bool converging = false;  // order > 0 and the finest error below the coarsest
  std::string figures;      // "d0 = 0.0146: 0.059; d0 = 0.0073: 0.176"
};
std::vector<ConvergenceFit> fit_convergence(const StudyTable& table);

}  // namespace washout::cli
