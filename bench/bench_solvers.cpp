// The pressure solvers on the same saved systems (bench_ppe_dump): iterations, set-up and solve
// time, and the memory the preconditioner or factor holds, one JSON line per system and
// solver; times are the fastest of --repeat R solves (set-up and solve each at its fastest),
// as wall time and as the calling thread's processor time (with OMP_NUM_THREADS=1 all the work,
// and robust when other work shares the cores).
// Each system starts from the guess the run gave it (the previous step's pressure)
// unless --cold. With --sequence one solver object takes the systems in the order given, as a
// run does, so a BoomerAMG set-up can serve later systems (--reuse N solves per set-up).
//   bench_solvers FILE.ppe ... [--solvers pcg,pcg_amg,cholmod] [--tolerance T] [--cold]
//                 [--repeat R] [--sequence] [--reuse N] [--strong S] [--aggressive L] [--interp I]
//                 [--pmax P] [--coarsen C] [--relax DOWN,UP] [--block-rows B]
//                 [--cycle-precision single|double]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "bench/ppe_system_file.hpp"
#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/solver_counters.hpp"

namespace {

int usage() {
  std::fprintf(
      stderr,
      "usage: bench_solvers FILE.ppe ... [--solvers pcg,pcg_amg,cholmod] [--tolerance T] "
      "[--cold] [--repeat R] [--sequence] [--reuse N] [--strong S] [--aggressive L] [--interp I] "
      "[--pmax P] [--coarsen C] [--relax DOWN,UP] [--block-rows B] "
      "[--cycle-precision single|double]\n");
  return 1;
}

std::unique_ptr<washout::LinearSolver> make(const std::string& name, double tolerance,
                                            const washout::AmgOptions& amg) {
  if (name == "pcg_amg") return washout::make_amg_pcg_solver(tolerance, 100000, amg);
  return washout::make_solver(name, tolerance, 100000);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files, solvers = {"pcg", "pcg_amg"};
  double tolerance = 1e-8;
  bool cold = false, sequence = false;
  int repeats = 1;
  washout::AmgOptions amg;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const bool has_value = k + 1 < argc;
    if (a == "--solvers" && has_value) {
      solvers.clear();
      std::stringstream list(argv[++k]);
      for (std::string item; std::getline(list, item, ',');) solvers.push_back(item);
    } else if (a == "--tolerance" && has_value) {
      tolerance = std::atof(argv[++k]);
    } else if (a == "--repeat" && has_value) {
      repeats = std::max(1, std::atoi(argv[++k]));
    } else if (a == "--cold") {
      cold = true;
    } else if (a == "--sequence") {
      sequence = true;
    } else if (a == "--reuse" && has_value) {
      amg.reuse_solves = std::atoi(argv[++k]);
    } else if (a == "--strong" && has_value) {
      amg.strong_threshold = std::atof(argv[++k]);
    } else if (a == "--aggressive" && has_value) {
      amg.aggressive_levels = std::atoi(argv[++k]);
    } else if (a == "--interp" && has_value) {
      amg.interpolation = std::atoi(argv[++k]);
    } else if (a == "--cycle-precision" && has_value) {
      const std::string p = argv[++k];
      if (p != "single" && p != "double") return usage();
      amg.single_precision_cycle = p == "single";
    } else if (a == "--block-rows" && has_value) {
      amg.cycle_block_rows = static_cast<std::size_t>(std::atol(argv[++k]));
    } else if (a == "--pmax" && has_value) {
      amg.max_interpolation_entries = std::atoi(argv[++k]);
    } else if (a == "--coarsen" && has_value) {
      amg.coarsening = std::atoi(argv[++k]);
    } else if (a == "--relax" && has_value) {  // down,up
      const std::string v = argv[++k];
      const auto comma = v.find(',');
      amg.relax_down = std::atoi(v.c_str());
      amg.relax_up = comma == std::string::npos ? amg.relax_down : std::atoi(v.c_str() + comma + 1);
    } else if (!a.empty() && a[0] != '-') {
      files.push_back(a);
    } else {
      return usage();
    }
  }
  if (files.empty() || solvers.empty()) return usage();

  for (const auto& name : solvers) {
    std::unique_ptr<washout::LinearSolver> solver;
    for (const auto& file : files) {
      const auto system = washout::bench::read_ppe_system(file);
      // The fastest of `repeats` solves from the same guess (a fresh solver each, unless
      // --sequence): the machine's other work only ever adds time.
      double seconds = 1e300, setup_seconds = 0.0, cpu_seconds = 1e300, setup_cpu = 0.0;
      washout::SolveReport report;
      std::vector<double> x;
      auto& c = washout::solver_counters();
      washout::SolverCounters best;
      for (int r = 0; r < (sequence ? 1 : repeats); ++r) {
        if (!sequence || !solver) solver = make(name, tolerance, amg);
        c = washout::SolverCounters{};
        x = cold ? std::vector<double>(system.A.rows, 0.0) : system.x0;
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = washout::thread_cpu_seconds();
        report = solver->solve(system.A, system.b, x);
        const double t =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double cpu = washout::thread_cpu_seconds() - cpu_start;
        if (r == 0 || c.setup_seconds < setup_seconds) setup_seconds = c.setup_seconds;
        if (r == 0 || c.setup_cpu_seconds < setup_cpu) setup_cpu = c.setup_cpu_seconds;
        cpu_seconds = std::min(cpu_seconds, cpu - c.setup_cpu_seconds);
        if (t - c.setup_seconds < seconds) {
          seconds = t - c.setup_seconds;
          best = c;
        }
      }
      c = best;
      const double residual = washout::relative_residual(system.A, system.b, x);
      std::printf(
          "{\"kind\": \"solver\", \"matrix\": \"%s\", \"rows\": %zu, \"nonzeros\": %zu, "
          "\"solver\": \"%s\", \"threads\": %d, \"tolerance\": %g, \"warm_start\": %s, "
          "\"iterations\": %d, \"converged\": %s, \"relative_residual\": %.3g, \"setups\": %ld, "
          "\"setup_seconds\": %.4g, \"solve_seconds\": %.4g, \"total_seconds\": %.4g, "
          "\"setup_cpu_seconds\": %.4g, \"solve_cpu_seconds\": %.4g, "
          "\"spmv_bytes_per_second\": %.4g, \"operator_complexity\": %.3g, "
          "\"setup_bytes\": %.4g, \"preconditioner_seconds\": %.4g, \"product_seconds\": %.4g}\n",
          file.c_str(), system.A.rows, system.A.nonzeros(), name.c_str(), omp_get_max_threads(),
          tolerance, cold ? "false" : "true", report.iterations,
          report.converged ? "true" : "false", residual, c.setups, setup_seconds, seconds,
          setup_seconds + seconds, setup_cpu, cpu_seconds,
          c.product_seconds > 0 ? c.product_bytes / c.product_seconds : 0.0, c.operator_complexity,
          c.setup_bytes, c.preconditioner_seconds, c.product_seconds);
      std::fflush(stdout);
    }
  }
  return 0;
}
