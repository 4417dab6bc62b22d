#pragma once
// Runs this same program as a child process (`washout run ...`), its stdout and stderr sent to
// a log file, so that a study survives a run that goes unstable or crashes.
#include <string>
#include <vector>

namespace washout::cli {

struct ChildResult {
  int exit_code = -1;  // the child's exit status, or -1 when a signal ended it
  int signal = 0;      // the signal that ended it, else 0
  double wall_seconds = 0;
  std::string error;  // set when the child could not be started
};

// The path of the running executable (/proc/self/exe).
std::string self_executable();
// Runs `program args...` with stdout and stderr appended to log_path; waits for it.
ChildResult run_child(const std::string& program, const std::vector<std::string>& args,
                      const std::string& log_path);

}  // namespace washout::cli
