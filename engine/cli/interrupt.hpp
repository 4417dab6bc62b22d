#pragma once
// SIGINT and SIGTERM during a run: the first asks the run to stop after the current step
// (a last frame, the body reports and the summary are written, the file closed, exit 4); a
// second ends the process at once with the same status. Every frame already written stays
// readable, as the file is flushed after each one.
#include <string>

#include "engine/sim/simulation.hpp"

namespace washout::cli {

// Installs the handlers (idempotent).
void install_interrupt_handlers();
// The signal received (SIGINT or SIGTERM), or 0.
int interrupt_signal();

// Stops the run loop at the next step or frame once a signal has arrived.
class InterruptObserver final : public RunObserver {
 public:
  bool on_step(const Simulation&, const StepReport&) override { return interrupt_signal() == 0; }
  bool on_frame(const Simulation&, std::size_t) override { return interrupt_signal() == 0; }
  std::string stop_reason() const override;
};

}  // namespace washout::cli
