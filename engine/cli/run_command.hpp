#pragma once
// `washout run SCENE.lua [--out DIR] [--set NAME=VALUE ...] [--threads N] [--quiet]`.
// run_scene() is the same pipeline as a function, used by tests, studies and benchmarks.
#include <cstdio>
#include <string>

#include "engine/cli/body_report.hpp"
#include "engine/cli/run_scoring.hpp"
#include "engine/lua/lua_scene.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::cli {

// Exit statuses of INTERFACE.md.
enum ExitCode { kSuccess = 0, kBadInput = 1, kUnstable = 2, kOutputFailed = 3, kInterrupted = 4 };

struct RunRequest {
  std::string scene_path;
  std::string out_dir;       // empty: runs/<scene name> (with restart_path: that file's folder)
  std::string restart_path;  // --restart RUN.h5: continue that run in that file
  lua::Overrides overrides;
  int threads = 0;  // 0: the scene's `threads` parameter, else all cores
  bool live_progress = false;
  bool render_frames = true;  // honour the scene's washout.frames{...}
  std::FILE* log = stdout;
  lua::LuaLimitSettings lua_limits;  // --lua-memory-limit, --lua-time-limit
};

struct RunOutcome {
  int exit_code = kSuccess;
  std::string error;  // for exit codes 1 and 3
  RunSummary summary;
  std::string h5_path;
  std::vector<BodyReport> bodies;            // one per /bodies/NAME: its CSV and summary
  RunCost cost;                              // also stored as root attributes of the run file
  std::vector<lua::ValidationScore> scores;  // a validation scene's errors (run_scoring.hpp)
};

RunOutcome run_scene(const RunRequest& request);
int run_command(int argc, char** argv);

}  // namespace washout::cli
