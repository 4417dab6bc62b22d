// Preconditioned conjugate gradient with a Jacobi (diagonal) preconditioner, warm-started from
// the caller's guess (the previous step's pressure). Dot products are summed in fixed blocks so
// that the result does not depend on the thread count's scheduling.
#include <cmath>

#include "engine/solvers/linear_solver.hpp"

namespace washout {
namespace {

constexpr std::size_t kBlock = 4096;
// Below this many unknowns a PCG iteration is a few microseconds of work: forking threads
// (and waiting at barriers when another process holds a core) would cost far more.
constexpr std::size_t kParallelRows = 20000;

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size(), blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial(blocks, 0.0);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (std::size_t k = 0; k < blocks; ++k) {
    double s = 0.0;
    const std::size_t end = std::min(n, (k + 1) * kBlock);
    for (std::size_t i = k * kBlock; i < end; ++i) s += a[i] * b[i];
    partial[k] = s;
  }
  double s = 0.0;
  for (double p : partial) s += p;
  return s;
}

class PcgSolver final : public LinearSolver {
 public:
  PcgSolver(double tolerance, int max_iterations)
      : tolerance_(tolerance), max_iterations_(max_iterations) {}
  std::string name() const override { return "pcg"; }

  SolveReport solve(const CsrMatrix& A, const std::vector<double>& b,
                    std::vector<double>& x) override {
    const std::size_t n = A.rows;
    x.resize(n, 0.0);
    inverse_diagonal_.assign(n, 1.0);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i)
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k)
        if (static_cast<std::size_t>(A.column[k]) == i && A.value[k] != 0.0)
          inverse_diagonal_[i] = 1.0 / A.value[k];

    SolveReport report;
    const double b_norm = std::sqrt(dot(b, b));
    if (n == 0 || b_norm == 0.0) {
      std::fill(x.begin(), x.end(), 0.0);
      return report;
    }
    r_.resize(n);
    z_.resize(n);
    A.multiply(x, q_);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) {
      r_[i] = b[i] - q_[i];
      z_[i] = inverse_diagonal_[i] * r_[i];
    }
    p_ = z_;
    double rz = dot(r_, z_);
    double r_norm = std::sqrt(dot(r_, r_));
    int it = 0;
    while (r_norm > tolerance_ * b_norm && it < max_iterations_) {
      A.multiply(p_, q_);
      const double step = rz / dot(p_, q_);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += step * p_[i];
        r_[i] -= step * q_[i];
        z_[i] = inverse_diagonal_[i] * r_[i];
      }
      const double rz_new = dot(r_, z_);
      const double beta = rz_new / rz;
      rz = rz_new;
#pragma omp parallel for schedule(static) if (n > kParallelRows)
      for (std::size_t i = 0; i < n; ++i) p_[i] = z_[i] + beta * p_[i];
      r_norm = std::sqrt(dot(r_, r_));
      ++it;
    }
    report.iterations = it;
    report.relative_residual = r_norm / b_norm;
    report.converged = r_norm <= tolerance_ * b_norm;
    return report;
  }

 private:
  double tolerance_;
  int max_iterations_;
  std::vector<double> inverse_diagonal_, r_, z_, p_, q_;
};

}  // namespace

double relative_residual(const CsrMatrix& A, const std::vector<double>& b,
                         const std::vector<double>& x) {
  std::vector<double> ax;
  A.multiply(x, ax);
  double rr = 0, bb = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    rr += (b[i] - ax[i]) * (b[i] - ax[i]);
    bb += b[i] * b[i];
  }
  return bb > 0 ? std::sqrt(rr / bb) : std::sqrt(rr);
}

std::unique_ptr<LinearSolver> make_pcg_solver(double tolerance, int max_iterations) {
  return std::make_unique<PcgSolver>(tolerance, max_iterations);
}

}  // namespace washout
