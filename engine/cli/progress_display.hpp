#pragma once
// Shows a run's progress. On a terminal: one line rewritten in place (simulated time / end
// time, step, dt, pressure-solver iterations and residual, wall time, ETA). Otherwise, or with
// --quiet: one line per output frame. After the first second, a note if other processes leave
// the run's threads too few cores (busy_cores.hpp).
#include <chrono>
#include <cstdio>

#include "engine/cli/busy_cores.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::cli {

class ProgressDisplay final : public RunObserver {
 public:
  ProgressDisplay(bool live, std::FILE* out) : live_(live), out_(out) {}
  void on_start(const Simulation& sim) override;
  bool on_step(const Simulation& sim, const StepReport& report) override;
  bool on_frame(const Simulation& sim, std::size_t frame) override;
  void on_finish(const Simulation& sim, const RunSummary& summary) override;
  // What other processes took of the cores since the run started (the run's cost reads it too).
  const BusyCoresProbe& busy_cores() const { return busy_cores_; }

 private:
  void print_line(const Simulation& sim, const StepReport& r, bool newline);
  void judge_busy_cores();
  bool live_;
  BusyCoresProbe busy_cores_;
  bool busy_cores_judged_ = false;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_print_;
};

void print_summary(std::FILE* out, const Simulation& sim, const RunSummary& summary);

}  // namespace washout::cli
