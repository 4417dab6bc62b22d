#include "engine/cli/study_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include "engine/cli/assignment_argument.hpp"
#include "engine/cli/child_run.hpp"
#include "engine/cli/run_command.hpp"
#include "engine/cli/study_table.hpp"
#include "engine/io/run_file_reader.hpp"
#include "engine/lua/lua_scene.hpp"

namespace washout::cli {
namespace {

const char* kStudyUsage =
    "usage: washout study SCENE.lua --vary NAME=V1,V2,... [--vary ...] [--repeat N] [--out DIR]\n"
    "                     [--set NAME=VALUE ...] [--threads N]\n"
    "\n"
    "Runs the scene once per combination of the --vary values (the cross product), each as a\n"
    "child `washout run` in DIR/run_K (its log in DIR/run_K/run.log), and writes DIR/study.csv:\n"
    "the varied values, status, particles, steps, wall seconds (min and median over --repeat),\n"
    "peak memory, PPE iterations per step and, for a scene that scores itself\n"
    "(washout.validation), its error. DIR/study.png (scripts/plot_study.py, Python with\n"
    "matplotlib) plots error against wall time and, when d0 varies, error against d0 with the\n"
    "observed convergence order. A run that goes unstable is a row with its status.\n"
    "  --vary NAME=V1,V2  a parameter and its values (repeatable: the cross product is run)\n"
    "  --repeat N         run each combination N times (wall time: min and median), default 1\n"
    "  --out DIR          study folder (default runs/study_<scene name>)\n"
    "  --set NAME=VALUE   fixed override for every run (repeatable)\n"
    "  --threads N        OpenMP threads of each run\n"
    "Exit status: 0 the study ran (whatever each run's status), 1 wrong scene or option,\n"
    "3 study.csv could not be written.\n";

struct StudyRequest {
  std::string scene_path, out_dir;
  std::vector<std::pair<std::string, std::vector<std::string>>> vary;
  lua::Overrides sets;
  int repeat = 1, threads = 0;
};

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream s(text);
  std::string part;
  while (std::getline(s, part, sep)) parts.push_back(part);
  return parts;
}

// The cross product of the --vary lists, the first varying slowest.
std::vector<std::vector<std::string>> combinations(const StudyRequest& r) {
  std::vector<std::vector<std::string>> all = {{}};
  for (const auto& [name, values] : r.vary) {
    std::vector<std::vector<std::string>> next;
    for (const auto& prefix : all)
      for (const auto& v : values) {
        auto c = prefix;
        c.push_back(v);
        next.push_back(c);
      }
    all = next;
  }
  return all;
}

std::string describe(const StudyRequest& r, const std::vector<std::string>& values) {
  std::string s;
  for (std::size_t k = 0; k < values.size(); ++k)
    s += (k ? ", " : "") + r.vary[k].first + " = " + values[k];
  return s;
}

std::string status_of(const ChildResult& c) {
  if (!c.error.empty()) return "not started";
  if (c.signal) return "crashed (signal " + std::to_string(c.signal) + ")";
  switch (c.exit_code) {
    case kSuccess:
      return "ok";
    case kBadInput:
      return "bad input";
    case kUnstable:
      return "unstable";
    case kOutputFailed:
      return "output failed";
    case 4:
      return "interrupted";
    default:
      return "exit " + std::to_string(c.exit_code);
  }
}

std::string duration(double s) {
  char b[32];
  if (s < 120)
    std::snprintf(b, sizeof b, "%.0f s", s);
  else if (s < 7200)
    std::snprintf(b, sizeof b, "%.1f min", s / 60);
  else
    std::snprintf(b, sizeof b, "%.1f h", s / 3600);
  return b;
}

// Reads a finished run's root attributes (run_scoring.hpp) and /stats into the row.
void read_run(const std::string& h5, StudyRow& row) {
  if (!std::filesystem::exists(h5)) return;
  try {
    io::RunFileReader run(h5);
    auto attr = [&](const char* name) {
      return run.has_attribute("/", name) ? run.double_attribute(name)
                                          : std::numeric_limits<double>::quiet_NaN();
    };
    row.particles = attr("particles");
    row.fluid_particles = attr("fluid_particles");
    row.steps = attr("steps");
    row.peak_rss_bytes = attr("peak_rss_bytes");
    row.threads = attr("threads");
    row.cores = attr("cores");
    row.cores_busy_elsewhere = attr("cores_busy_elsewhere");
    if (run.has("/stats/ppe_iterations")) {
      const auto it = run.read_doubles("/stats/ppe_iterations");
      if (!it.empty())
        row.ppe_iterations_per_step = std::accumulate(it.begin(), it.end(), 0.0) / it.size();
    }
    row.errors.clear();
    row.bounds.clear();
    if (run.has_attribute("/", "error_names")) {
      for (const auto& name : split(run.string_attribute("error_names"), ',')) {
        row.errors.emplace_back(name, attr(("error_" + name).c_str()));
        row.bounds.emplace_back(name, attr(("error_bound_" + name).c_str()));
      }
      row.error_metric = run.string_attribute("error_metric");
    }
  } catch (const io::RunFileError&) {
    // A run killed while writing: the row keeps its status and no figures.
  }
}

int parse(int argc, char** argv, StudyRequest& r) {
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    auto value = [&](const char* option) -> std::string {
      if (k + 1 >= argc) {
        std::fprintf(stderr, "washout study: %s needs a value\n%s", option, kStudyUsage);
        std::exit(kBadInput);
      }
      return argv[++k];
    };
    auto whole = [&](const char* option, int minimum) {
      const std::string v = value(option);
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || n < minimum) {
        std::fprintf(stderr, "washout study: %s needs a whole number >= %d, got '%s'\n", option,
                     minimum, v.c_str());
        std::exit(kBadInput);
      }
      return static_cast<int>(n);
    };
    if (arg == "--help" || arg == "-h") {
      std::printf("%s", kStudyUsage);
      std::exit(kSuccess);
    } else if (arg == "--vary" || arg == "--set") {
      const std::string kv = value(arg.c_str());
      const auto assignment = split_assignment(kv);
      if (!assignment || assignment->second.empty()) {
        std::fprintf(stderr, "washout study: %s needs NAME=%s, got '%s'\n", arg.c_str(),
                     arg == "--vary" ? "V1,V2,..." : "VALUE", kv.c_str());
        return kBadInput;
      }
      const auto& [name, text] = *assignment;
      if (arg == "--set") {
        r.sets.emplace_back(name, text);
        continue;
      }
      for (const auto& [other, values] : r.vary)
        if (other == name) {
          std::fprintf(stderr, "washout study: --vary %s given twice\n", name.c_str());
          return kBadInput;
        }
      auto values = split(text, ',');
      for (const auto& v : values)
        if (v.empty()) {
          std::fprintf(stderr, "washout study: --vary %s has an empty value in '%s'\n",
                       name.c_str(), kv.c_str());
          return kBadInput;
        }
      r.vary.emplace_back(name, values);
    } else if (arg == "--repeat") {
      r.repeat = whole("--repeat", 1);
    } else if (arg == "--threads") {
      r.threads = whole("--threads", 1);
    } else if (arg == "--out") {
      r.out_dir = value("--out");
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "washout study: unknown option '%s'\n%s", arg.c_str(), kStudyUsage);
      return kBadInput;
    } else if (r.scene_path.empty()) {
      r.scene_path = arg;
    } else {
      std::fprintf(stderr, "washout study: one scene at a time ('%s' and '%s')\n",
                   r.scene_path.c_str(), arg.c_str());
      return kBadInput;
    }
  }
  if (r.scene_path.empty()) {
    std::fprintf(stderr, "washout study: which scene?\n%s", kStudyUsage);
    return kBadInput;
  }
  if (r.vary.empty()) {
    std::fprintf(stderr, "washout study: nothing to vary (--vary NAME=V1,V2,...)\n%s", kStudyUsage);
    return kBadInput;
  }
  return kSuccess;
}

// Loads the scene with each combination's overrides before running anything, so that a
// misspelt --vary name or an impossible value stops the study at once. Returns the run
// file's name and the dimension, or exits with status 1.
struct SceneFacts {
  std::string file_name;
  int dim = 2;
  bool validates = false;
};
int check_scene(const StudyRequest& r, const std::vector<std::vector<std::string>>& combos,
                SceneFacts& facts) {
  for (const auto& values : combos) {
    lua::Overrides overrides = r.sets;
    for (std::size_t k = 0; k < values.size(); ++k)
      overrides.emplace_back(r.vary[k].first, values[k]);
    try {
      lua::LuaScene scene(r.scene_path, overrides);
      facts.file_name = scene.model().output.file_name;
      facts.dim = scene.model().params.dim;
      facts.validates = scene.validates();
    } catch (const SceneError& e) {
      std::string what = e.what();
      // A --vary value reaches the scene as a --set: name the option the user typed.
      bool varied = false;
      for (const auto& v : r.vary) varied = varied || v.first == e.parameter();
      const std::string set_prefix = "--set " + e.parameter();
      if (varied && what.rfind(set_prefix, 0) == 0)
        what = "--vary " + what.substr(6);
      else if (!e.where().empty() && what.rfind(e.where(), 0) != 0)
        what = e.where() + ": " + what;
      std::fprintf(stderr, "washout study: %s (with %s)\n", what.c_str(),
                   describe(r, values).c_str());
      return kBadInput;
    }
  }
  return kSuccess;
}

// Relative cost of a run, for the ETA: (1/d0)^(dim+1) when d0 varies, else the same for all.
double work_of(const StudyRequest& r, const std::vector<std::string>& values, int dim) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (r.vary[k].first == "d0") {
      const double d0 = std::atof(values[k].c_str());
      if (d0 > 0) return std::pow(1.0 / d0, dim + 1);
    }
  return 1.0;
}

std::string scripts_dir() {
  const char* env = std::getenv("WASHOUT_SCRIPTS");
  return env ? env : WASHOUT_SCRIPTS_DIR;
}

// Draws study.png with scripts/plot_study.py; says why when it cannot.
void plot(const std::string& csv, const std::string& png, const std::string& out_dir) {
  const std::string python = "/usr/bin/python3";
  const std::string script = scripts_dir() + "/plot_study.py";
  if (access(python.c_str(), X_OK) != 0) {
    std::fprintf(stderr, "study: no plot: %s not found (study.csv is written)\n", python.c_str());
    return;
  }
  const std::string log = (std::filesystem::path(out_dir) / "plot.log").string();
  std::filesystem::remove(log);
  const ChildResult c = run_child(python, {script, csv, png}, log);
  if (c.exit_code == 0) {
    std::printf("plot: %s\n", png.c_str());
    return;
  }
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::fprintf(stderr, "study: no plot (study.csv is written): %s%s\n",
               c.error.empty() ? (script + " failed: ").c_str() : c.error.c_str(), last.c_str());
}

}  // namespace

int run_study_command(int argc, char** argv) {
  StudyRequest r;
  if (const int status = parse(argc, argv, r); status != kSuccess) return status;
  const auto combos = combinations(r);
  SceneFacts facts;
  if (const int status = check_scene(r, combos, facts); status != kSuccess) return status;
  if (r.out_dir.empty())
    r.out_dir = (std::filesystem::path("runs") /
                 ("study_" + std::filesystem::path(r.scene_path).stem().string()))
                    .string();
  std::error_code ec;
  std::filesystem::create_directories(r.out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "washout study: cannot create '%s': %s\n", r.out_dir.c_str(),
                 ec.message().c_str());
    return kOutputFailed;
  }
  const std::string exe = self_executable();
  const std::string csv = (std::filesystem::path(r.out_dir) / "study.csv").string();
  if (!facts.validates)
    std::fprintf(stderr, "study: %s declares no reference (washout.validation): cost only\n",
                 r.scene_path.c_str());

  StudyTable table;
  for (const auto& [name, values] : r.vary) table.names.push_back(name);
  double work_total = 0, work_done = 0, elapsed = 0;
  for (const auto& values : combos) work_total += work_of(r, values, facts.dim);
  const int n = static_cast<int>(combos.size());
  bool interrupted = false;
  for (int k = 0; k < n && !interrupted; ++k) {
    StudyRow row;
    row.values = combos[k];
    char name[32];
    std::snprintf(name, sizeof name, "run_%02d", k + 1);
    const auto run_dir = std::filesystem::path(r.out_dir) / name;
    std::filesystem::create_directories(run_dir, ec);
    std::vector<std::string> args = {"run", r.scene_path, "--out", run_dir.string(), "--quiet"};
    if (r.threads > 0) args.insert(args.end(), {"--threads", std::to_string(r.threads)});
    for (const auto& [pname, pvalue] : r.sets)
      args.insert(args.end(), {"--set", pname + "=" + pvalue});
    for (std::size_t v = 0; v < row.values.size(); ++v)
      args.insert(args.end(), {"--set", r.vary[v].first + "=" + row.values[v]});
    for (int rep = 0; rep < r.repeat; ++rep) {
      std::fprintf(
          stderr, "study: run %d of %d (%s)%s ...", k + 1, n, describe(r, row.values).c_str(),
          r.repeat > 1
              ? (" repeat " + std::to_string(rep + 1) + " of " + std::to_string(r.repeat)).c_str()
              : "");
      std::fflush(stderr);
      const std::string log = (run_dir / "run.log").string();
      if (rep == 0) std::filesystem::remove(log, ec);
      const ChildResult c = run_child(exe, args, log);
      row.exit_code = c.exit_code;
      row.status = status_of(c);
      elapsed += c.wall_seconds;
      // A run that stopped early is a row too: its cost is the time until it stopped.
      if (c.exit_code == 0 || rep == 0) row.wall_seconds.push_back(c.wall_seconds);
      std::fprintf(stderr, " %s in %s\n", row.status.c_str(), duration(c.wall_seconds).c_str());
      if (!c.error.empty()) std::fprintf(stderr, "study: %s\n", c.error.c_str());
      if (c.exit_code == 4 || c.signal == SIGINT || c.signal == SIGTERM) interrupted = true;
      if (c.exit_code != 0) break;  // an unstable run is not repeated
    }
    read_run((run_dir / facts.file_name).string(), row);
    if (!row.errors.empty() && row.status == "ok")
      std::fprintf(stderr, "study:   error %.4g, %.0f particles, %.0f steps\n",
                   row.errors.front().second, row.particles, row.steps);
    table.rows.push_back(row);
    if (!table.write_csv(csv)) {
      std::fprintf(stderr, "washout study: cannot write %s\n", csv.c_str());
      return kOutputFailed;
    }
    work_done += work_of(r, row.values, facts.dim);
    if (k + 1 < n && work_done > 0)
      std::fprintf(stderr, "study: %d of %d done, %s so far, ETA %s\n", k + 1, n,
                   duration(elapsed).c_str(),
                   duration(elapsed / work_done * (work_total - work_done)).c_str());
  }
  if (table.rows.empty()) return kBadInput;
  std::printf("study: %s, %zu run(s) in %s\n", csv.c_str(), table.rows.size(),
              duration(elapsed).c_str());
  for (const auto& row : table.rows) {
    std::printf("  %-32s %-10s", describe(r, row.values).c_str(), row.status.c_str());
    if (std::isfinite(row.particles)) std::printf(" %8.0f particles", row.particles);
    std::printf(" %9.1f s", row.wall_min());
    if (!row.errors.empty()) std::printf("  error %.4g", row.errors.front().second);
    if (row.waited_for_cores())
      std::printf("  (other processes kept %.1f cores busy: its threads waited)",
                  row.cores_busy_elsewhere);
    std::printf("\n");
  }
  for (const auto& f : fit_convergence(table)) {
    const std::string label = f.score + (f.group.empty() ? "" : " (" + f.group + ")");
    if (f.points < 2)
      std::printf("convergence of %s: fewer than two completed runs (%s)\n", label.c_str(),
                  f.figures.c_str());
    else if (f.converging)
      std::printf("convergence of %s: observed order %.2f in d0 (%s)\n", label.c_str(), f.order,
                  f.figures.c_str());
    else
      std::printf(
          "convergence of %s: not converging, the error does not fall with d0 "
          "(fitted order %.2f; %s)\n",
          label.c_str(), f.order, f.figures.c_str());
  }
  plot(csv, (std::filesystem::path(r.out_dir) / "study.png").string(), r.out_dir);
  return interrupted ? 4 : kSuccess;
}

}  // namespace washout::cli
