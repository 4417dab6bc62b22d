#include "engine/cli/progress_display.hpp"

#include <omp.h>

#include <cmath>
#include <string>

namespace washout::cli {
namespace {

constexpr double kBusyCoresWindow = 1.0;  // seconds of run over which the cores are judged

std::string clock_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

}  // namespace

void ProgressDisplay::on_start(const Simulation& sim) {
  start_ = last_print_ = std::chrono::steady_clock::now();
  busy_cores_ = BusyCoresProbe();
  busy_cores_judged_ = false;
  const auto& p = sim.particles();
  std::fprintf(out_,
               "washout %s: %s, %dD, %zu fluid + %zu boundary particles, d0 = %g m, h = %g m\n",
               WASHOUT_VERSION, sim.model().scene_name.c_str(), p.dim, p.fluid_count,
               p.size() - p.fluid_count, sim.params().d0, sim.context().h);
  std::string stages;
  for (const Stage stage : sim.plan()) {
    if (!stages.empty()) stages += ", ";
    stages += stage_name(stage);
  }
  std::fprintf(out_, "  step: %s\n", stages.c_str());
  std::fflush(out_);
}

void ProgressDisplay::print_line(const Simulation& sim, const StepReport& r, bool newline) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double end = sim.params().end_time;
  const double eta = sim.time() > 0 ? elapsed * (end - sim.time()) / sim.time() : NAN;
  std::fprintf(
      out_,
      "%st = %.4f / %.4f s  step %ld  dt %.2e s (%s)  PPE %d it (res %.1e)  wall %s  ETA %s%s",
      newline ? "" : "\r", sim.time(), end, sim.step_count(), r.dt, step_limit_name(r.dt_limit),
      r.ppe_iterations, r.ppe_residual, clock_text(elapsed).c_str(), clock_text(eta).c_str(),
      newline ? "\n" : "   ");
  std::fflush(out_);
}

// Judged once, over the run's first second: the run's threads take what the scheduler gives them
// (spinning at barriers included), and what the machine spent beyond that went elsewhere.
void ProgressDisplay::judge_busy_cores() {
  if (busy_cores_judged_ || busy_cores_.seconds() < kBusyCoresWindow) return;
  busy_cores_judged_ = true;
  const std::string note = busy_cores_.note(omp_get_max_threads(), kBusyCoresWindow);
  if (note.empty()) return;
  std::fprintf(out_, "%s%s\n", live_ ? "\n" : "", note.c_str());
  std::fflush(out_);
}

bool ProgressDisplay::on_step(const Simulation& sim, const StepReport& report) {
  judge_busy_cores();
  if (!live_) return true;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_print_).count() > 0.2) {
    last_print_ = now;
    print_line(sim, report, false);
  }
  return true;
}

bool ProgressDisplay::on_frame(const Simulation& sim, std::size_t frame) {
  if (live_ || frame == 0) return true;
  std::fprintf(out_, "frame %4zu  ", frame);
  print_line(sim, sim.last_report(), true);
  return true;
}

void ProgressDisplay::on_finish(const Simulation& sim, const RunSummary& summary) {
  if (live_) std::fprintf(out_, "\n");
  print_summary(out_, sim, summary);
}

void print_summary(std::FILE* out, const Simulation& sim, const RunSummary& s) {
  const char* status = s.status == RunStatus::Completed        ? "completed"
                       : s.status == RunStatus::StoppedByScene ? "stopped by the scene"
                                                               : "UNSTABLE";
  std::fprintf(out, "run %s at t = %.4f s after %ld steps in %.2f s wall time\n", status, s.time,
               s.steps, s.wall_seconds);
  if (!s.message.empty()) std::fprintf(out, "  %s\n", s.message.c_str());
  const double particle_steps = double(s.fluid_particles) * double(s.steps);
  std::fprintf(
      out,
      "  particles: %zu fluid, %zu boundary (%.0f of them seen by the fluid, mean over the "
      "steps); %.3g fluid particle-steps/s\n",
      s.fluid_particles, s.boundary_particles, s.mean_active_boundary,
      s.wall_seconds > 0 ? particle_steps / s.wall_seconds : 0.0);
  // "auto" resolves by the unknowns' count at each solve: name what it took at the last one.
  const std::string& requested = sim.params().solver;
  const std::string solver = requested == "auto" && !s.pressure_solver.empty()
                                 ? "auto: " + s.pressure_solver + " at the last solve"
                                 : requested;
  std::fprintf(out, "  pressure solve: %.1f iterations per step (%s)\n", s.mean_ppe_iterations,
               solver.c_str());
  std::fprintf(out, "  fluid particles found inside walls: %ld\n", s.wall_crossings);
  if (s.gap_relocations > 0)
    std::fprintf(out,
                 "  of those, moved to a free place (out of a closing gap, or off another "
                 "particle): %ld\n",
                 s.gap_relocations);
  if (s.bodies_asleep_steps > 0)
    std::fprintf(out, "  bodies asleep at rest, dry (no contact sub-steps): %ld of the %ld steps\n",
                 s.bodies_asleep_steps, s.steps);
  if (s.retired_particles > 0)
    std::fprintf(out,
                 "  fluid particles retired as they left the domain: %zu (%.2g %% of the fluid; "
                 "the first, %s)\n",
                 s.retired_particles,
                 100.0 * double(s.retired_particles) / double(s.fluid_particles),
                 s.first_retirement.c_str());
  if (!s.output_path.empty())
    std::fprintf(out, "  output: %s (%zu frames, last at t = %.4f s)\n", s.output_path.c_str(),
                 s.frames, s.last_frame_time);
  double total = 0;
  for (const auto& st : s.stage_seconds) total += st.second;
  std::fprintf(out, "  stages that ran (wall seconds, share):\n");
  for (const auto& [name, seconds] : s.stage_seconds)
    std::fprintf(out, "    %-14s %9.3f  %5.1f %%\n", name.c_str(), seconds,
                 total > 0 ? 100.0 * seconds / total : 0.0);
  std::fflush(out);
}

}  // namespace washout::cli
