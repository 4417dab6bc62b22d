#include "engine/cli/run_scoring.hpp"

#include <sys/resource.h>

#include <cmath>

#include "engine/cli/busy_cores.hpp"
#include "engine/io/run_file_writer.hpp"

namespace washout::cli {

long peak_rss_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return usage.ru_maxrss * 1024L;  // Linux reports kilobytes
}

RunCost run_cost(const RunSummary& summary) {
  RunCost c;
  c.wall_seconds = summary.wall_seconds;
  c.fluid_particles = summary.fluid_particles;
  c.particles = summary.fluid_particles + summary.boundary_particles;
  c.steps = summary.steps;
  c.peak_rss_bytes = peak_rss_bytes();
  return c;
}

void write_run_scores(const std::string& run_file, const RunCost& cost,
                      const std::vector<lua::ValidationScore>& scores) {
  std::vector<std::pair<std::string, double>> numbers = {
      {"wall_seconds", cost.wall_seconds},
      {"particles", static_cast<double>(cost.particles)},
      {"fluid_particles", static_cast<double>(cost.fluid_particles)},
      {"steps", static_cast<double>(cost.steps)},
      {"peak_rss_bytes", static_cast<double>(cost.peak_rss_bytes)},
      {"threads", static_cast<double>(cost.threads)},
      {"cores", static_cast<double>(cost.cores)},
      {"cores_busy_elsewhere", cost.cores_busy_elsewhere}};
  std::vector<std::pair<std::string, std::string>> texts;
  std::string names;
  for (const auto& s : scores) {
    names += (names.empty() ? "" : ",") + s.name;
    numbers.emplace_back("error_" + s.name, s.error);
    numbers.emplace_back("error_bound_" + s.name, s.bound);
  }
  if (!scores.empty()) {
    const auto& primary = scores.front();
    numbers.emplace_back("error", primary.error);
    numbers.emplace_back("error_bound", primary.bound);
    texts = {
        {"error_metric", primary.metric}, {"reference", primary.reference}, {"error_names", names}};
  }
  io::write_root_attributes(run_file, numbers, texts);
}

void print_run_scores(std::FILE* out, const RunCost& cost,
                      const std::vector<lua::ValidationScore>& scores) {
  for (const auto& s : scores) {
    if (!s.failure.empty()) {
      std::fprintf(out, "error %s: not computed: %s\n", s.name.c_str(), s.failure.c_str());
      continue;
    }
    std::fprintf(out, "error %s = %.4g (%s; against %s", s.name.c_str(), s.error, s.metric.c_str(),
                 s.reference.c_str());
    if (std::isfinite(s.bound))
      std::fprintf(out, "; bound %.4g%s", s.bound, s.error <= s.bound ? "" : ", EXCEEDED");
    std::fprintf(out, ")\n");
  }
  std::fprintf(out,
               "cost: wall %.2f s, %zu particles (%zu fluid), %ld steps, peak memory %.0f MB, "
               "%d threads",
               cost.wall_seconds, cost.particles, cost.fluid_particles, cost.steps,
               cost.peak_rss_bytes / 1048576.0, cost.threads);
  if (std::isfinite(cost.cores_busy_elsewhere))
    std::fprintf(out, ", other processes kept %.1f of %d cores busy%s", cost.cores_busy_elsewhere,
                 cost.cores,
                 threads_lack_cores(cost.threads, cost.cores, cost.cores_busy_elsewhere)
                     ? " (the threads waited for cores: not the machine's time)"
                     : "");
  std::fprintf(out, "\n");
}

}  // namespace washout::cli
