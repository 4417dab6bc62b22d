#include "engine/cli/run_command.hpp"

#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

#include "engine/cli/assignment_argument.hpp"
#include "engine/cli/body_report.hpp"
#include "engine/cli/frame_output.hpp"
#include "engine/cli/interrupt.hpp"
#include "engine/cli/progress_display.hpp"
#include "engine/cli/restart.hpp"
#include "engine/io/run_file_reader.hpp"
#include "engine/io/run_file_writer.hpp"
#include "engine/io/run_recorder.hpp"

namespace washout::cli {
namespace {

const char* kRunUsage =
    "usage: washout run SCENE.lua [--out DIR] [--set NAME=VALUE ...] [--threads N] [--quiet]\n"
    "                             [--restart RUN.h5]\n"
    "       washout run --list-parameters\n"
    "\n"
    "Runs a scene and writes one HDF5 file (plus its .xdmf and, if the scene asks, PNG frames)\n"
    "into DIR (default: runs/<scene name>/).\n"
    "  --out DIR          output folder, created if missing\n"
    "  --set NAME=VALUE   override a scene or engine parameter (repeatable), e.g. --set d0=0.005\n"
    "  --threads N        OpenMP threads (default: the scene's `threads`, else all cores)\n"
    "  --quiet            one line per output frame instead of a live progress line\n"
    "  --restart RUN.h5   continue that run of this scene (same --set values; end_time may\n"
    "                     change) from its last complete frame, in RUN.h5 itself\n"
    "  --list-parameters  print every engine parameter with its unit, default and meaning\n"
    "  --lua-time-limit S     stop (exit 1) the scene script or a callback or motion function\n"
    "                         that has not returned after S seconds (default 60)\n"
    "  --lua-memory-limit MIB the most memory the scene's Lua code may hold (default 1024)\n"
    "Exit status: 0 success, 1 wrong scene or input, 2 unstable simulation, 3 output failed,\n"
    "4 interrupted by SIGINT or SIGTERM (last frame, body reports and summary written; a second\n"
    "signal stops at once).\n";

std::string format_default(const ParameterValue& v) {
  if (auto d = std::get_if<double>(&v)) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", *d);
    return b;
  }
  if (auto s = std::get_if<std::string>(&v)) return "\"" + *s + "\"";
  const auto& list = std::get<std::vector<double>>(v);
  std::string o = "{";
  for (std::size_t k = 0; k < list.size(); ++k) o += (k ? ", " : "") + std::to_string(list[k]);
  return o + "}";
}

// The body reports of a run that ended with an error: best effort, the error is what to report.
void try_report_bodies(RunOutcome& outcome, const std::string& out_dir, const Vec3& gravity,
                       std::FILE* log) {
  try {
    outcome.bodies = report_bodies(outcome.h5_path, out_dir, gravity, log);
  } catch (const std::exception& e) {
    std::fprintf(log, "note: no body reports: %s\n", e.what());
  }
}

}  // namespace

RunOutcome run_scene(const RunRequest& request) {
  RunOutcome outcome;
  bool run_started = false;  // the run file exists and holds this run's steps
  Vec3 gravity = Vec3::Zero();
  std::string report_dir;
  try {
    lua::LuaScene scene(request.scene_path, request.overrides, request.lua_limits);
    Model& model = scene.model();
    const int threads = request.threads > 0 ? request.threads : model.params.threads;
    if (threads > 0) omp_set_num_threads(threads);
    std::string out_dir = request.out_dir.empty()
                              ? (std::filesystem::path("runs") / model.scene_name).string()
                              : request.out_dir;
    std::optional<io::Checkpoint> resume;
    if (!request.restart_path.empty()) {
      // The run goes on in its own file; body CSVs and PNG frames beside it.
      namespace fs = std::filesystem;
      const fs::path folder = fs::path(request.restart_path).parent_path();
      std::error_code same_error;
      if (!request.out_dir.empty() &&
          !fs::equivalent(folder.empty() ? "." : folder, request.out_dir, same_error)) {
        outcome.exit_code = kBadInput;
        outcome.error = "--restart continues " + request.restart_path +
                        " in its own folder; --out " + request.out_dir + " names another";
        return outcome;
      }
      resume = load_restart(request.restart_path, model);
      out_dir = folder.empty() ? "." : folder.string();
      std::fprintf(request.log, "continuing %s from frame %lld (t = %.9g s, step %lld)\n",
                   request.restart_path.c_str(), static_cast<long long>(resume->frame),
                   resume->number("time"), static_cast<long long>(resume->count("step")));
      const long long threads_then = resume->count("threads");
      const int threads_now = omp_get_max_threads();
      if (threads_then != threads_now)
        std::fprintf(request.log,
                     "note: that run used %lld threads, this one %d: the continuation is not "
                     "bitwise the one an uninterrupted run would have made\n",
                     threads_then, threads_now);
      if (resume->number("time") >= model.params.end_time - 1e-9 * model.params.output_interval)
        std::fprintf(request.log,
                     "note: the run already reached end_time = %g s; give a later one "
                     "(--set end_time=...) to go on\n",
                     model.params.end_time);
    }
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) {
      outcome.exit_code = kOutputFailed;
      outcome.error = "cannot create output folder '" + out_dir + "': " + ec.message();
      return outcome;
    }
    outcome.h5_path = resume ? request.restart_path
                             : (std::filesystem::path(out_dir) / model.output.file_name).string();
    report_dir = out_dir;
    const lua::FrameRequest frames = scene.frames();
    Simulation sim(model);
    gravity = sim.params().gravity;
    // The run file is kept by an observer like any other; it is closed when the run returns,
    // before the body reports read it back.
    io::RunRecorder recorder(outcome.h5_path, resume ? &*resume : nullptr);
    ProgressDisplay progress(request.live_progress, request.log);
    std::vector<RunObserver*> observers = {&recorder, &progress};
    if (auto* callbacks = scene.callbacks()) observers.push_back(callbacks);
    std::unique_ptr<RunObserver> frame_writer;
    if (request.render_frames && frames.enabled) {
      frame_writer =
          make_frame_output(frames, (std::filesystem::path(out_dir) / "frames").string());
      observers.push_back(frame_writer.get());
    }
    InterruptObserver interrupt;  // last, so that its reason names the signal
    observers.push_back(&interrupt);
    run_started = true;
    outcome.summary = sim.run(observers, resume ? &*resume : nullptr);
    // Each body's CSV and wash-out summary, also after an unstable run (its file stays readable).
    outcome.bodies = report_bodies(outcome.h5_path, out_dir, gravity, request.log);
    if (outcome.summary.status == RunStatus::Unstable) outcome.exit_code = kUnstable;
    const bool interrupted = interrupt_signal() != 0;
    // Cost and, for a completed validation scene, the error against its reference.
    outcome.cost = run_cost(outcome.summary);
    outcome.cost.threads = omp_get_max_threads();
    outcome.cost.cores = progress.busy_cores().cores();  // whether the wall time is the machine's
    outcome.cost.cores_busy_elsewhere = progress.busy_cores().busy_elsewhere();
    if (outcome.summary.status != RunStatus::Unstable && !interrupted && scene.validates())
      outcome.scores = scene.score(outcome.h5_path);
    write_run_scores(outcome.h5_path, outcome.cost, outcome.scores);
    print_run_scores(request.log, outcome.cost, outcome.scores);
    for (const auto& s : outcome.scores)
      if (!s.failure.empty()) {
        outcome.exit_code = kBadInput;
        outcome.error = "the scene's score '" + s.name + "' failed: " + s.failure;
      }
    if (interrupted && outcome.exit_code == kSuccess) {
      outcome.exit_code = kInterrupted;
      char when[64];
      std::snprintf(when, sizeof when, " at t = %g s", outcome.summary.time);
      outcome.error =
          outcome.summary.message + when + "; every frame up to then is in " + outcome.h5_path;
    }
  } catch (const RestartError& e) {
    outcome.exit_code = kBadInput;
    outcome.error = e.what();
  } catch (const io::CheckpointError& e) {  // the state does not fit the scene's particles
    outcome.exit_code = kBadInput;
    outcome.error = "cannot restart from " + request.restart_path + ": " + std::string(e.what());
  } catch (const SceneError& e) {
    outcome.exit_code = kBadInput;
    // A callback or motion function that failed mid-run: the steps before it are in the file,
    // and their body reports are made as after any other stopped run.
    if (run_started) try_report_bodies(outcome, report_dir, gravity, request.log);
    std::string where = e.where();
    const std::string what = e.what();
    // Lua messages already start with "file:line:"; others get the location prefixed.
    if (!where.empty() && what.rfind(where, 0) != 0)
      outcome.error = where + ": " + what;
    else
      outcome.error = what;
    if (!e.parameter().empty() && outcome.error.find(e.parameter()) == std::string::npos)
      outcome.error += " (parameter '" + e.parameter() + "')";
  } catch (const std::invalid_argument& e) {  // a setting the engine cannot build, e.g. a
    outcome.exit_code = kBadInput;            // periodic length too short for the kernel
    outcome.error = e.what();
  } catch (const io::OutputError& e) {
    outcome.exit_code = kOutputFailed;
    outcome.error = e.what();
  } catch (const io::RunFileError& e) {  // the body report could not read the run back
    outcome.exit_code = kOutputFailed;
    outcome.error = e.what();
  }
  return outcome;
}

int run_command(int argc, char** argv) {
  RunRequest request;
  bool quiet = false;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    auto value = [&](const char* option) -> std::string {
      if (k + 1 >= argc) {
        std::fprintf(stderr, "washout run: %s needs a value\n%s", option, kRunUsage);
        std::exit(kBadInput);
      }
      return argv[++k];
    };
    if (arg == "--help" || arg == "-h") {
      std::printf("%s", kRunUsage);
      return kSuccess;
    } else if (arg == "--list-parameters") {
      std::printf("| parameter | unit | default | meaning |\n|---|---|---|---|\n");
      for (const auto& info : ParameterSet::engine_table())
        std::printf("| `%s` | %s | `%s` | %s |\n", info.name, info.unit,
                    format_default(info.default_value).c_str(), info.doc);
      return kSuccess;
    } else if (arg == "--out") {
      request.out_dir = value("--out");
    } else if (arg == "--set") {
      const std::string kv = value("--set");
      const auto assignment = split_assignment(kv);
      if (!assignment) {
        std::fprintf(stderr, "washout run: --set needs NAME=VALUE, got '%s'\n", kv.c_str());
        return kBadInput;
      }
      request.overrides.push_back(*assignment);
    } else if (arg == "--threads") {
      const std::string v = value("--threads");
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || n < 1) {
        std::fprintf(stderr, "washout run: --threads needs a positive whole number, got '%s'\n",
                     v.c_str());
        return kBadInput;
      }
      request.threads = static_cast<int>(n);
    } else if (arg == "--lua-time-limit" || arg == "--lua-memory-limit") {
      const std::string v = value(arg.c_str());
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !(x > 0) || !std::isfinite(x)) {
        std::fprintf(stderr, "washout run: %s needs a positive number, got '%s'\n", arg.c_str(),
                     v.c_str());
        return kBadInput;
      }
      (arg == "--lua-time-limit" ? request.lua_limits.seconds : request.lua_limits.memory_mib) = x;
    } else if (arg == "--restart") {
      request.restart_path = value("--restart");
    } else if (arg == "--quiet" || arg == "-q") {
      quiet = true;
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "washout run: unknown option '%s'\n%s", arg.c_str(), kRunUsage);
      return kBadInput;
    } else if (request.scene_path.empty()) {
      request.scene_path = arg;
    } else {
      std::fprintf(stderr, "washout run: one scene at a time ('%s' and '%s')\n",
                   request.scene_path.c_str(), arg.c_str());
      return kBadInput;
    }
  }
  if (request.scene_path.empty()) {
    std::fprintf(stderr, "washout run: which scene?\n%s", kRunUsage);
    return kBadInput;
  }
  request.live_progress = !quiet && isatty(fileno(stdout));
  install_interrupt_handlers();
  const RunOutcome outcome = run_scene(request);
  if (!outcome.error.empty()) std::fprintf(stderr, "error: %s\n", outcome.error.c_str());
  return outcome.exit_code;
}

}  // namespace washout::cli
