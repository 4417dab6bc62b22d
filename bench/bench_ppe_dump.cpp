// Saves pressure systems of a real run for the solver comparison (bench_solvers): runs a scene
// as `washout run` does and writes the systems of the chosen solves (1 = the first step's) to
// DIR/NAME_sK.ppe (bench/ppe_system_file.hpp), then stops the run as an interrupt does (the
// step finishes, the file is closed). Set end_time so that the run reaches the last one.
// Prints each file with its rows and non-zeros.
//   bench_ppe_dump SCENE.lua --name NAME --solves K1,K2,... --dir DIR [--threads N]
//                  [--set NAME=VALUE ...]
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>

#include "bench/ppe_system_file.hpp"
#include "engine/cli/assignment_argument.hpp"
#include "engine/cli/interrupt.hpp"
#include "engine/cli/run_command.hpp"
#include "engine/solvers/solver_counters.hpp"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: bench_ppe_dump SCENE.lua --name NAME --solves K1,K2,... --dir DIR "
               "[--threads N] [--set NAME=VALUE ...]\n");
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = washout::cli;
  cli::RunRequest request;
  request.render_frames = false;
  std::string name, dir;
  std::set<long> wanted;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const bool has_value = k + 1 < argc;
    if (a == "--name" && has_value) {
      name = argv[++k];
    } else if (a == "--dir" && has_value) {
      dir = argv[++k];
    } else if (a == "--threads" && has_value) {
      request.threads = std::atoi(argv[++k]);
    } else if (a == "--solves" && has_value) {
      std::stringstream list(argv[++k]);
      for (std::string item; std::getline(list, item, ',');) wanted.insert(std::atol(item.c_str()));
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
  if (request.scene_path.empty() || name.empty() || dir.empty() || wanted.empty()) return usage();

  long solve = 0;
  std::size_t written = 0;
  washout::set_system_observer(
      [&](const washout::CsrMatrix& A, const std::vector<double>& b, const std::vector<double>& x) {
        if (!wanted.count(++solve)) return;
        const std::string path = dir + "/" + name + "_s" + std::to_string(solve) + ".ppe";
        washout::bench::write_ppe_system(path, A, b, x);
        std::printf("%s: %zu rows, %zu non-zeros\n", path.c_str(), A.rows, A.nonzeros());
        std::fflush(stdout);
        // The last one: stop the run as an interrupt does, after this step.
        if (++written == wanted.size()) std::raise(SIGINT);
      });
  cli::install_interrupt_handlers();
  std::FILE* quiet = std::fopen("/dev/null", "w");
  request.log = quiet ? quiet : stderr;
  request.out_dir = dir + "/run_" + name;
  const auto out = cli::run_scene(request);
  if (quiet) std::fclose(quiet);
  if (written < wanted.size() && out.exit_code != cli::kSuccess) {
    std::fprintf(stderr, "bench_ppe_dump: the run failed (exit %d): %s %s\n", out.exit_code,
                 out.error.c_str(), out.summary.message.c_str());
    return out.exit_code;
  }
  if (written < wanted.size()) {
    std::fprintf(stderr, "bench_ppe_dump: the run made %ld solves, fewer than asked for\n", solve);
    return 1;
  }
  return 0;
}
