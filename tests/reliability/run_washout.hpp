#pragma once
// Runs the washout program as a user does: a child process with stdout and stderr captured,
// killed if it outlives a time bound (a hang is a failure, not a stuck test).
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace washout::test {

struct ProgramResult {
  int status = -1;  // exit status, or -1 when a signal ended it
  int signal = 0;
  bool timed_out = false;
  std::string output;  // stdout and stderr together
};

// Splits on spaces (the corpus has no quoted arguments).
inline std::vector<std::string> split_words(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// The whole of a text file (a run's log), empty if it is not there yet.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline pid_t start_washout(const std::vector<std::string>& args, const std::string& log_path) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> argv;
    std::string exe = WASHOUT_EXE;
    argv.push_back(exe.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

inline ProgramResult wait_washout(pid_t pid, const std::string& log_path, double limit_seconds) {
  ProgramResult r;
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        limit_seconds) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (WIFEXITED(status)) r.status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  std::ifstream in(log_path);
  std::stringstream text;
  text << in.rdbuf();
  r.output = text.str();
  return r;
}

// Waits until the log holds `text` (a run reaching a frame) or `limit_seconds` pass.
inline void wait_for_log(const std::string& log_path, const std::string& text,
                         double limit_seconds) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
             limit_seconds &&
         read_text(log_path).find(text) == std::string::npos)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

inline ProgramResult run_washout(const std::vector<std::string>& args, const std::string& log_path,
                                 double limit_seconds) {
  return wait_washout(start_washout(args, log_path), log_path, limit_seconds);
}

}  // namespace washout::test
