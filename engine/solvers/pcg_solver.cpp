// Preconditioned conjugate gradient, warm-started from the caller's guess (the previous step's
// pressure), with a preconditioner chosen by name: Jacobi (the diagonal, "pcg") or one
// BoomerAMG V-cycle ("pcg_amg", hypre_amg.cpp). The loop is the same for both, so the stopping
// test |b - A x| / |b| <= tolerance means the same thing whichever preconditions. Dot products
// are summed in fixed blocks so that the result does not depend on the thread count's
// scheduling.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/solvers/linear_solver.hpp"
#include "engine/solvers/preconditioner.hpp"
#include "engine/solvers/solver_counters.hpp"
#include "engine/solvers/symmetric_product.hpp"

namespace washout {
namespace {

constexpr std::size_t kBlock = 4096;
// Below this many unknowns a vector pass of the loop is a few microseconds of work: forking
// threads (and waiting at barriers when another process holds a core) would cost as much.
// (The product, by far the largest part, decides by its non-zeros: sparse_matrix.cpp.)
constexpr std::size_t kParallelRows = 4096;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Two sums over [0, n), taken in fixed blocks so that they do not depend on the threads:
// terms(i) gives the i-th term of each (and may update the vectors at i on the way).
template <class Terms>
std::pair<double, double> blocked_sums(std::size_t n, Terms&& terms) {
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial_b(blocks, 0.0), partial_c(blocks, 0.0);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (std::size_t k = 0; k < blocks; ++k) {
    double sb = 0.0, sc = 0.0;
    const std::size_t end = std::min(n, (k + 1) * kBlock);
    for (std::size_t i = k * kBlock; i < end; ++i) {
      const auto [tb, tc] = terms(i);
      sb += tb;
      sc += tc;
    }
    partial_b[k] = sb;
    partial_c[k] = sc;
  }
  double sb = 0.0, sc = 0.0;
  for (std::size_t k = 0; k < blocks; ++k) {
    sb += partial_b[k];
    sc += partial_c[k];
  }
  return {sb, sc};
}

// Both sums a.b and a.c in one pass.
std::pair<double, double> dots(const std::vector<double>& a, const std::vector<double>& b,
                               const std::vector<double>& c) {
  return blocked_sums(a.size(), [&](std::size_t i) {
    return std::pair<double, double>{a[i] * b[i], a[i] * c[i]};
  });
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  return dots(a, b, b).first;
}

class JacobiPreconditioner final : public Preconditioner {
 public:
  void prepare(const CsrMatrix& A, bool same_matrix) override {
    if (same_matrix && inverse_diagonal_.size() == A.rows) return;
    const std::size_t n = A.rows;
    inverse_diagonal_.assign(n, 1.0);
    // The assembly stores each row's diagonal first (ppe_matrix.cpp): found there, the row is not
    // scanned (a scan of every entry was 2 % of the same-case 3D dam break at a/20).
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t first = A.row_start[i], end = A.row_start[i + 1];
      if (first < end && static_cast<std::size_t>(A.column[first]) == i) {
        if (A.value[first] != 0.0) inverse_diagonal_[i] = 1.0 / A.value[first];
        continue;
      }
      for (std::int64_t k = first; k < end; ++k)
        if (static_cast<std::size_t>(A.column[k]) == i && A.value[k] != 0.0)
          inverse_diagonal_[i] = 1.0 / A.value[k];
    }
    auto& counters = solver_counters();
    counters.setup_bytes = std::max(counters.setup_bytes, double(n * sizeof(double)));
  }
  const std::vector<double>* inverse_diagonal() const override { return &inverse_diagonal_; }
  void apply(const std::vector<double>& r, std::vector<double>& z) override {
    const std::size_t n = r.size();
    z.resize(n);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) z[i] = inverse_diagonal_[i] * r[i];
  }

 private:
  std::vector<double> inverse_diagonal_;
};

class PcgSolver final : public LinearSolver {
 public:
  PcgSolver(std::string name, std::unique_ptr<Preconditioner> preconditioner, double tolerance,
            int max_iterations, bool upper_triangle)
      : name_(std::move(name)),
        preconditioner_(std::move(preconditioner)),
        tolerance_(tolerance),
        max_iterations_(max_iterations),
        upper_triangle_(upper_triangle) {}
  std::string name() const override { return name_; }

  SolveReport solve(const CsrMatrix& A, const std::vector<double>& b,
                    std::vector<double>& x) override {
    return iterate(A, b, x, false, tolerance_);
  }
  SolveReport solve_again(const CsrMatrix& A, const std::vector<double>& b,
                          std::vector<double>& x) override {
    return iterate(A, b, x, true, tolerance_);
  }
  SolveReport solve_again_to(const CsrMatrix& A, const std::vector<double>& b,
                             std::vector<double>& x, double tolerance) override {
    return iterate(A, b, x, true, tolerance);
  }
  // The same CG iterations for each system as solve_again_to, side by side: each step's
  // products of all the systems still iterating in one read of the matrix (full rows), the
  // rest of the step (cg_start, cg_step) the very code a single solve runs.
  std::vector<SolveReport> solve_many_again_to(const CsrMatrix& A,
                                               const std::vector<const std::vector<double>*>& b,
                                               const std::vector<std::vector<double>*>& x,
                                               const std::vector<double>& tolerance) override {
    const std::size_t count = b.size(), n = A.rows;
    std::vector<SolveReport> reports(count);
    if (count == 0) return reports;
    preconditioner_->prepare(A, true);
    take_matrix(A, true);
    many_.resize(count);
    std::vector<double> b_norm(count);
    std::vector<std::size_t> active;
    std::vector<const std::vector<double>*> from;
    std::vector<std::vector<double>*> to;
    for (std::size_t k = 0; k < count; ++k) {
      x[k]->resize(n, 0.0);
      b_norm[k] = std::sqrt(dot(*b[k], *b[k]));
      if (n == 0 || b_norm[k] == 0.0) {
        std::fill(x[k]->begin(), x[k]->end(), 0.0);
        reports[k].converged = true;
        continue;
      }
      active.push_back(k);
      from.push_back(x[k]);
      to.push_back(&many_[k].q);
    }
    multiply_many_counted(A, from, to);
    for (std::size_t k : active) cg_start(many_[k], *b[k]);
    const auto unconverged = [&](std::size_t k) {
      return many_[k].r_norm > tolerance[k] * b_norm[k] && reports[k].iterations < max_iterations_;
    };
    std::erase_if(active, [&](std::size_t k) { return !unconverged(k); });
    while (!active.empty()) {
      from.clear();
      to.clear();
      for (std::size_t k : active) from.push_back(&many_[k].p), to.push_back(&many_[k].q);
      multiply_many_counted(A, from, to);
      for (std::size_t k : active) {
        cg_step(many_[k], *x[k]);
        ++reports[k].iterations;
      }
      std::erase_if(active, [&](std::size_t k) { return !unconverged(k); });
    }
    for (std::size_t k = 0; k < count; ++k) {
      if (b_norm[k] == 0.0) continue;
      reports[k].relative_residual = many_[k].r_norm / b_norm[k];
      reports[k].converged = many_[k].r_norm <= tolerance[k] * b_norm[k];
    }
    return reports;
  }

 private:
  // With upper_triangle_ (Jacobi CG), the products use the upper triangle alone where it pays
  // (symmetric_product.hpp), taken once per matrix: another right-hand side of the same matrix
  // reuses it.
  void take_matrix(const CsrMatrix& A, bool same_matrix) {
    if (same_matrix && product_taken_) return;
    if (upper_triangle_)
      symmetric_.build(A);  // declined: the full rows multiply
    else
      symmetric_.clear();
    product_taken_ = true;
  }
  void multiply(const CsrMatrix& A, const std::vector<double>& v, std::vector<double>& out) {
    const auto start = std::chrono::steady_clock::now();
    if (symmetric_.ready())
      symmetric_.multiply(v, out);
    else
      A.multiply(v, out);
    auto& c = solver_counters();
    c.product_seconds += seconds_since(start);
    c.product_bytes += symmetric_.ready() ? symmetric_.product_bytes() : csr_product_bytes(A);
    ++c.products;
  }
  void multiply_many_counted(const CsrMatrix& A, const std::vector<const std::vector<double>*>& v,
                             const std::vector<std::vector<double>*>& out) {
    if (v.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    multiply_many(A, v, out);
    auto& c = solver_counters();
    c.product_seconds += seconds_since(start);
    c.product_bytes += csr_product_bytes(A) + 16.0 * double(A.rows) * double(v.size() - 1);
    c.products += static_cast<long>(v.size());
  }
  void precondition(const std::vector<double>& r, std::vector<double>& z) {
    const auto start = std::chrono::steady_clock::now();
    preconditioner_->apply(r, z);
    solver_counters().preconditioner_seconds += seconds_since(start);
  }

  // One right-hand side's CG state: residual r, preconditioned z, direction p, product q,
  // r.z and |r|.
  struct System {
    std::vector<double> r, z, p, q;
    double rz = 0.0, r_norm = 0.0;
  };

  // With q = A x: r = b - q, z = M^-1 r, p = z.
  void cg_start(System& s, const std::vector<double>& b) {
    const std::size_t n = b.size();
    s.r.resize(n);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) s.r[i] = b[i] - s.q[i];
    precondition(s.r, s.z);
    s.p = s.z;
    const auto [rz, rr] = dots(s.r, s.z, s.r);
    s.rz = rz;
    s.r_norm = std::sqrt(rr);
  }

  // With q = A p: one CG step of x and the state.
  void cg_step(System& s, std::vector<double>& x) {
    const std::size_t n = x.size();
    const double step = s.rz / dot(s.p, s.q);
    const auto [rz_new, rr_new] = advance(s, step, x);
    const double beta = rz_new / s.rz;
    s.rz = rz_new;
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) s.p[i] = s.z[i] + beta * s.p[i];
    s.r_norm = std::sqrt(rr_new);
  }

  // x += step p, r -= step q, z = M^-1 r, and the sums r.z and r.r. With a diagonal M all in one
  // pass over fixed blocks, the same operations in the same order as the passes apart (the
  // compiler may fuse a multiply and an add elsewhere: the same bits with -ffp-contract=off, a
  // last-digit difference without); its time then counts as the loop's, not the preconditioner's.
  std::pair<double, double> advance(System& s, double step, std::vector<double>& x) {
    const std::size_t n = x.size();
    const std::vector<double>* diagonal = preconditioner_->inverse_diagonal();
    if (!diagonal) {
#pragma omp parallel for schedule(static) if (n > kParallelRows)
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += step * s.p[i];
        s.r[i] -= step * s.q[i];
      }
      precondition(s.r, s.z);
      return dots(s.r, s.z, s.r);
    }
    const double* inverse = diagonal->data();
    s.z.resize(n);
    return blocked_sums(n, [&](std::size_t i) {
      x[i] += step * s.p[i];
      s.r[i] -= step * s.q[i];
      s.z[i] = inverse[i] * s.r[i];
      return std::pair<double, double>{s.r[i] * s.z[i], s.r[i] * s.r[i]};
    });
  }

  SolveReport iterate(const CsrMatrix& A, const std::vector<double>& b, std::vector<double>& x,
                      bool same_matrix, double tolerance) {
    const std::size_t n = A.rows;
    x.resize(n, 0.0);
    if (!same_matrix) product_taken_ = false;  // even if this solve returns before taking it
    SolveReport report;
    const double b_norm = std::sqrt(dot(b, b));
    if (n == 0 || b_norm == 0.0) {
      std::fill(x.begin(), x.end(), 0.0);
      return report;
    }
    preconditioner_->prepare(A, same_matrix);
    take_matrix(A, same_matrix);
    System& s = one_;
    multiply(A, x, s.q);
    cg_start(s, b);
    int it = 0;
    while (s.r_norm > tolerance * b_norm && it < max_iterations_) {
      multiply(A, s.p, s.q);
      cg_step(s, x);
      ++it;
    }
    // Only a new matrix's first solve tells whether a reused set-up still fits it: another
    // right-hand side of the same matrix (the body coupling's responses) starts from another
    // guess and stops at another tolerance, so its iterations say nothing about staleness
    // (counting them rebuilt BoomerAMG's hierarchy every 2-3 steps of the 3D wash-out).
    if (!same_matrix) preconditioner_->solved(it);
    report.iterations = it;
    report.relative_residual = s.r_norm / b_norm;
    report.converged = s.r_norm <= tolerance * b_norm;
    return report;
  }

  std::string name_;
  std::unique_ptr<Preconditioner> preconditioner_;
  double tolerance_;
  int max_iterations_;
  System one_;                // a single solve's state
  std::vector<System> many_;  // solve_many_again_to's, one per right-hand side
  bool upper_triangle_ = true;
  SymmetricProduct symmetric_;
  bool product_taken_ = false;
};

}  // namespace

std::unique_ptr<Preconditioner> make_jacobi_preconditioner() {
  return std::make_unique<JacobiPreconditioner>();
}

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
  return std::make_unique<PcgSolver>("pcg", make_jacobi_preconditioner(), tolerance, max_iterations,
                                     /*upper_triangle=*/true);
}

std::unique_ptr<LinearSolver> make_aggregation_pcg_solver(double tolerance, int max_iterations) {
  return std::make_unique<PcgSolver>("pcg_agg", make_aggregation_preconditioner(), tolerance,
                                     max_iterations, /*upper_triangle=*/true);
}

std::unique_ptr<LinearSolver> make_amg_pcg_solver(double tolerance, int max_iterations,
                                                  const AmgOptions& options) {
  // Full rows: BoomerAMG's V-cycle is most of an iteration and its set-up needs the full rows
  // anyway; the triangle's second copy of half the matrix cost 104 bytes a particle at the
  // same-case a/40 and saved no time (docs/performance.md, nineteenth session).
  return std::make_unique<PcgSolver>("pcg_amg", make_boomeramg_preconditioner(options), tolerance,
                                     max_iterations, /*upper_triangle=*/false);
}

}  // namespace washout
