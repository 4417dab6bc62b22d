// The solver by name, and the counters every solve adds to (solver_counters.hpp).
#include <chrono>
#include <ctime>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/solver_counters.hpp"

namespace washout {
namespace {

SolverCounters counters;
AmgOptions amg_options;
SystemObserver observer;

// Counts what its solver does: solves, iterations, size and time.
class CountedSolver final : public LinearSolver {
 public:
  explicit CountedSolver(std::unique_ptr<LinearSolver> inner) : inner_(std::move(inner)) {}
  std::string name() const override { return inner_->name(); }
  bool direct() const override { return inner_->direct(); }
  SolveReport solve(const CsrMatrix& A, const std::vector<double>& b,
                    std::vector<double>& x) override {
    if (observer) observer(A, b, x);
    return count(A, [&] { return inner_->solve(A, b, x); });
  }
  SolveReport solve_again(const CsrMatrix& A, const std::vector<double>& b,
                          std::vector<double>& x) override {
    return count(A, [&] { return inner_->solve_again(A, b, x); });
  }
  SolveReport solve_again_to(const CsrMatrix& A, const std::vector<double>& b,
                             std::vector<double>& x, double tolerance) override {
    return count(A, [&] { return inner_->solve_again_to(A, b, x, tolerance); });
  }
  std::vector<SolveReport> solve_many_again_to(const CsrMatrix& A,
                                               const std::vector<const std::vector<double>*>& b,
                                               const std::vector<std::vector<double>*>& x,
                                               const std::vector<double>& tolerance) override {
    const auto start = std::chrono::steady_clock::now();
    const auto reports = inner_->solve_many_again_to(A, b, x, tolerance);
    counters.solve_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const SolveReport& report : reports) record(A, report);
    return reports;
  }

 private:
  template <class Solve>
  SolveReport count(const CsrMatrix& A, Solve solve) {
    const auto start = std::chrono::steady_clock::now();
    const SolveReport report = solve();
    counters.solve_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    record(A, report);
    return report;
  }
  // One solve in the counters (its time is counted by the caller).
  void record(const CsrMatrix& A, const SolveReport& report) {
    ++counters.solves;
    counters.solver = inner_->name();
    counters.iterations += report.iterations;
    counters.rows += double(A.rows);
    counters.nonzeros += double(A.nonzeros());
  }
  std::unique_ptr<LinearSolver> inner_;
};

}  // namespace

SolverCounters& solver_counters() { return counters; }
AmgOptions& default_amg_options() { return amg_options; }

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
void set_system_observer(SystemObserver o) { observer = std::move(o); }
const SystemObserver& system_observer() { return observer; }

std::string resolve_solver(const std::string& requested, int dim, std::size_t unknowns,
                           bool body_coupled) {
  if (requested != "auto") return requested;
  // By the comparisons in docs/performance.md ("The default", "The twenty-fourth session", "The
  // twenty-fifth session"): CHOLMOD's exact solve in 2D for small systems coupled to dynamic
  // bodies (their landing steps are sensitive to an inexact solve at 1e-6) and below 1,000
  // unknowns (a millisecond); otherwise CG with the aggregates' coarse correction (pcg_agg) below
  // 100,000 unknowns, where its coarse system factorises in tens of milliseconds (it solved the
  // same-case 3D dam break 1.6-2.4 times as fast as Jacobi CG at 8,000 unknowns and as BoomerAMG
  // CG at 64,000; the 2D Lobovsky run at H/60 in 0.7 of BoomerAMG CG's time), and BoomerAMG CG
  // from 100,000, where that factorisation grows too fast (1.5 s at 216,000 against 0.4 s for
  // BoomerAMG's set-up).
  if (dim == 2 && (unknowns <= 1000 || (body_coupled && unknowns <= 60000))) return "cholmod";
  return unknowns < 100000 ? "pcg_agg" : "pcg_amg";
}

std::unique_ptr<LinearSolver> make_solver(const std::string& name, double tolerance,
                                          int max_iterations) {
  std::unique_ptr<LinearSolver> solver;
  if (name == "cholmod")
    solver = make_cholmod_solver();
  else if (name == "pcg")
    solver = make_pcg_solver(tolerance, max_iterations);
  else if (name == "pcg_agg")
    solver = make_aggregation_pcg_solver(tolerance, max_iterations);
  else if (name == "pcg_amg")
    solver = make_amg_pcg_solver(tolerance, max_iterations, amg_options);
  else
    throw SolverError("unknown pressure solver '" + name +
                      "' (cholmod, pcg, pcg_agg, pcg_amg, auto)");
  return std::make_unique<CountedSolver>(std::move(solver));
}

}  // namespace washout
