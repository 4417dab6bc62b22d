#pragma once
// After a run: its cost (wall time, particles, steps, peak memory) and, for a scene that
// declares washout.validation{...}, its error against the reference. Both are printed and
// stored as root attributes of the run file, where `washout study` collects them
// (docs/validation.md). Application side only: the physics core knows nothing of references.
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "engine/lua/lua_validation.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::cli {

struct RunCost {
  double wall_seconds = 0;
  std::size_t particles = 0;  // fluid + wall + body particles
  std::size_t fluid_particles = 0;
  long steps = 0;
  long peak_rss_bytes = 0;  // of this process (getrusage), so of this run in `washout run`
  // Whether the wall time is the machine's: the run's threads, the machine's cores and the cores
  // other processes kept busy over the run (busy_cores.hpp; NaN where unknown). A run whose
  // threads did not all find a core ran slower than the machine can (docs/performance.md).
  int threads = 0, cores = 0;
  double cores_busy_elsewhere = std::numeric_limits<double>::quiet_NaN();
};

RunCost run_cost(const RunSummary& summary);
long peak_rss_bytes();

// Root attributes wall_seconds, particles, fluid_particles, steps, peak_rss_bytes, threads,
// cores, cores_busy_elsewhere and, when
// scores are given, error, error_metric, reference, error_bound (the primary, the first score)
// plus error_NAME / error_bound_NAME for every score and error_names (comma separated).
// Throws io::OutputError.
void write_run_scores(const std::string& run_file, const RunCost& cost,
                      const std::vector<lua::ValidationScore>& scores);

// "error 0.0593 (front: RMS of ...; bound 0.08)" lines and the cost line.
void print_run_scores(std::FILE* out, const RunCost& cost,
                      const std::vector<lua::ValidationScore>& scores);

}  // namespace washout::cli
