#include "engine/cli/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>

#include "engine/cli/run_command.hpp"

namespace washout::cli {
namespace {

std::atomic<int> received{0};

extern "C" void on_signal(int sig) {
  int expected = 0;
  if (!received.compare_exchange_strong(expected, sig)) {
    // The second signal: the user wants out now. The file holds every frame flushed so far.
    static const char message[] = "\nwashout: second signal, stopping at once\n";
    [[maybe_unused]] const auto n = write(STDERR_FILENO, message, sizeof message - 1);
    _exit(kInterrupted);
  }
  static const char message[] =
      "\nwashout: interrupted; finishing the step and writing the last frame "
      "(signal again to stop at once)\n";
  [[maybe_unused]] const auto n = write(STDERR_FILENO, message, sizeof message - 1);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() { return received.load(); }

std::string InterruptObserver::stop_reason() const {
  return std::string("interrupted by ") + (interrupt_signal() == SIGINT ? "SIGINT" : "SIGTERM");
}

}  // namespace washout::cli
