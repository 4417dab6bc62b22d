// One benchmark case: runs a scene as `washout run` does and prints one JSON line with what the
// run cost (bench/run composes the cases; docs/performance.md explains every field). A
// benchmark, never a test: the figures depend on the machine and on what else runs on it.
//   bench_case --case NAME SCENE.lua [--dim D] [--out DIR] [--threads N]
//              [--set NAME=VALUE ...] [--stream BYTES_PER_SECOND] [--amg-reuse N] [--amg-cycle
//              threaded|hypre]
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/cli/assignment_argument.hpp"
#include "engine/cli/run_command.hpp"
#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/solver_counters.hpp"

namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (static_cast<unsigned char>(c) < 0x20)
      out += ' ';
    else
      out += c;
  }
  return out + "\"";
}

// A number as JSON has it: not finite is null.
std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

int usage() {
  std::fprintf(stderr,
               "usage: bench_case --case NAME SCENE.lua [--dim D] [--out DIR] [--threads N] "
               "[--set NAME=VALUE ...] [--stream BYTES_PER_SECOND] [--amg-reuse N] [--amg-cycle "
               "threaded|hypre]\n");
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = washout::cli;
  cli::RunRequest request;
  request.render_frames = false;
  std::string label;
  double stream = std::nan("");
  int dim = 0;  // the case's dimension as bench/run states it (the summary does not carry it)
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const bool has_value = k + 1 < argc;
    if (a == "--case" && has_value) {
      label = argv[++k];
    } else if (a == "--out" && has_value) {
      request.out_dir = argv[++k];
    } else if (a == "--threads" && has_value) {
      request.threads = std::atoi(argv[++k]);
    } else if (a == "--amg-reuse" && has_value) {
      washout::default_amg_options().reuse_solves = std::atoi(argv[++k]);
    } else if (a == "--amg-cycle" && has_value) {
      const std::string cycle = argv[++k];
      if (cycle != "threaded" && cycle != "hypre") {
        std::fprintf(stderr, "bench_case: --amg-cycle takes threaded or hypre, not '%s'\n",
                     cycle.c_str());
        return 1;
      }
      washout::default_amg_options().threaded_cycle = cycle == "threaded";
    } else if (a == "--dim" && has_value) {
      dim = std::atoi(argv[++k]);
    } else if (a == "--stream" && has_value) {
      stream = std::atof(argv[++k]);
    } else if (a == "--set" && has_value) {
      const auto assignment = cli::split_assignment(argv[++k]);
      if (!assignment) return usage();
      request.overrides.push_back(*assignment);
    } else if (!a.empty() && a[0] != '-' && request.scene_path.empty()) {
      request.scene_path = a;
    } else {
      return usage();
    }
  }
  if (request.scene_path.empty() || label.empty()) return usage();

  std::FILE* quiet = std::fopen("/dev/null", "w");
  request.log = quiet ? quiet : stderr;
  const auto out = cli::run_scene(request);
  if (quiet) std::fclose(quiet);
  // A short window of a validation scene may end before its score has enough points: the run
  // itself is what is measured, so a score that could not be computed is no failure here.
  bool score_failed = false;
  for (const auto& score : out.scores) score_failed = score_failed || !score.failure.empty();
  const bool ran =
      out.exit_code == cli::kSuccess || (out.exit_code == cli::kBadInput && score_failed &&
                                         out.summary.status != washout::RunStatus::Unstable);
  if (!ran) {
    std::fprintf(stderr, "bench_case %s: the run failed (exit %d): %s %s\n", label.c_str(),
                 out.exit_code, out.error.c_str(), out.summary.message.c_str());
    return out.exit_code;
  }

  const auto& s = out.summary;
  const auto& c = washout::solver_counters();
  const double particles = double(s.fluid_particles + s.boundary_particles);
  const double steps = double(s.steps);
  double stage_total = 0.0;
  for (const auto& st : s.stage_seconds) stage_total += st.second;
  std::string shares;
  for (const auto& [name, seconds] : s.stage_seconds)
    shares += (shares.empty() ? "" : ", ") + quoted(name) + ": " +
              number(stage_total > 0 ? seconds / stage_total : NAN);
  const double spmv = c.product_seconds > 0 ? c.product_bytes / c.product_seconds : NAN;
  const double per_solve = c.solves > 0 ? 1.0 / double(c.solves) : NAN;
  std::string error = "null";
  if (!out.scores.empty() && out.scores.front().failure.empty())
    error = "{\"name\": " + quoted(out.scores.front().name) +
            ", \"value\": " + number(out.scores.front().error) +
            ", \"metric\": " + quoted(out.scores.front().metric) + "}";
  // Every score the scene computed, by name (the Martin & Moyce cases: front, front_speed, ...).
  std::string errors;
  for (const auto& score : out.scores)
    if (score.failure.empty())
      errors += (errors.empty() ? "" : ", ") + quoted(score.name) + ": " + number(score.error);
  errors = "{" + errors + "}";
  std::printf("{\"kind\": \"case\", \"case\": %s, \"scene\": %s, \"dim\": %s, ",
              quoted(label).c_str(), quoted(request.scene_path).c_str(),
              dim > 0 ? std::to_string(dim).c_str() : "null");
  std::printf("\"particles\": {\"fluid\": %zu, \"wall\": %zu, \"active_wall\": %s}, ",
              s.fluid_particles, s.boundary_particles, number(s.mean_active_boundary).c_str());
  std::printf(
      "\"steps\": %ld, \"simulated_seconds\": %s, \"wall_seconds\": %s, "
      "\"seconds_per_step\": %s, \"fluid_particle_steps_per_second\": %s, "
      "\"particle_steps_per_second\": %s, ",
      s.steps, number(s.time).c_str(), number(s.wall_seconds).c_str(),
      number(s.wall_seconds / steps).c_str(),
      number(double(s.fluid_particles) * steps / s.wall_seconds).c_str(),
      number(particles * steps / s.wall_seconds).c_str());
  std::printf("\"stage_share\": {%s}, ", shares.c_str());
  std::printf(
      "\"ppe\": {\"solver\": %s, \"mean_iterations\": %s, \"iterations_per_solve\": %s, "
      "\"solves\": %ld, \"mean_unknowns\": %s, \"mean_nonzeros\": %s, \"setups\": %ld, "
      "\"setup_seconds\": %s, \"solve_seconds\": %s, \"operator_complexity\": %s, "
      "\"setup_bytes\": %s, \"spmv_bytes_per_second\": %s, \"spmv_over_stream\": %s}, ",
      quoted(c.solver).c_str(), number(s.mean_ppe_iterations).c_str(),
      number(double(c.iterations) * per_solve).c_str(), c.solves,
      number(c.rows * per_solve).c_str(), number(c.nonzeros * per_solve).c_str(), c.setups,
      number(c.setup_seconds).c_str(), number(c.solve_seconds).c_str(),
      number(c.operator_complexity > 0 ? c.operator_complexity : NAN).c_str(),
      number(c.setup_bytes).c_str(), number(spmv).c_str(), number(spmv / stream).c_str());
  std::printf(
      "\"peak_rss_bytes\": %ld, \"bytes_per_particle\": %s, \"threads\": %d, \"error\": %s, "
      "\"errors\": %s}\n",
      out.cost.peak_rss_bytes, number(double(out.cost.peak_rss_bytes) / particles).c_str(),
      omp_get_max_threads(), error.c_str(), errors.c_str());
  return 0;
}
