#pragma once
// One multigrid V-cycle on a hierarchy built elsewhere (BoomerAMG's, hypre_amg.cpp), run on all
// threads. Debian's hypre is built without OpenMP, so its own V-cycle runs on one thread while
// the conjugate gradient around it runs on all: at the paper's resolution the V-cycles were
// most of the pressure solve (docs/performance.md). The cycle is hypre's V(1,1) with the
// lexicographic Gauss-Seidel sweep split into row blocks ("hybrid" Gauss-Seidel): each block
// sweeps its own rows in order, reading the other blocks' values from before the sweep, so the
// blocks run in parallel. Going down the sweep is forward, coming up backward over the same
// blocks: the cycle stays a symmetric operator, as CG needs. The blocks depend on the matrix's
// size only, never on the thread count, so a run's results do not change with the threads;
// with one block the cycle is hypre's (tests/unit/test_threaded_vcycle.cpp).
#include <Eigen/Dense>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace washout {

// A square or rectangular matrix in compressed rows, borrowed (hypre's arrays, or the cycle's
// own single-precision copy of their values). Rows of the square ones hold their diagonal
// first, as hypre keeps them.
template <class Value>
struct CsrOf {
  std::size_t rows = 0, columns = 0;
  const int* row_start = nullptr;
  const int* column = nullptr;
  const Value* value = nullptr;
};
using CsrView = CsrOf<double>;

// Single precision: the cycle reads its matrices' values as floats (the rows' sums, the vectors
// and the coarsest solve stay in double). The pressure solve at the paper's resolution is bound
// by the memory traffic of the fine matrix, which each V-cycle reads three times (two sweeps and
// a residual) at 12 bytes a non-zero; as floats 8. The cycle is still a fixed symmetric
// operator (the same rounded matrix in both sweeps, R = P^T from the same rounded P), so CG
// stays CG; only the preconditioner is a little less exact (docs/performance.md, thirty-first
// session).
enum class CyclePrecision { double_precision, single_precision };

class ThreadedVCycle {
 public:
  // At least two levels. levels[l] is A_l for l >= 1 (level 0, the fine matrix, is given to
  // set_fine(): a hierarchy reused across steps takes each step's new matrix there);
  // interpolation[l] is P_l, from level l + 1 to level l. The views must stay valid until the
  // next build(). block_rows: the rows per Gauss-Seidel block (0: the default below).
  void build(const std::vector<CsrView>& levels, const std::vector<CsrView>& interpolation,
             std::size_t block_rows = 0,
             CyclePrecision precision = CyclePrecision::double_precision);

  // The fine matrix of the next apply()s (as many rows as P_0); again whenever its values
  // change (in single precision they are copied).
  void set_fine(const CsrView& fine);

  // z = M^-1 r, one V-cycle from z = 0 on the fine matrix.
  void apply(const double* r, double* z);

  // Forgets the hierarchy and frees the cycle's own memory (before a new build()).
  void release();

  // Blocks of at least this many rows: a level smaller than two of them is swept on one
  // thread, whole (the coarse levels), and a fine level of 2D or 3D rows splits into a few
  // blocks whose boundaries hold a small share of the couplings.
  static constexpr std::size_t kDefaultBlockRows = 16384;

  // The Gauss-Seidel blocks of a level of this many rows: one below two blocks' worth, else
  // about rows / block_rows rounded up to a multiple of four.
  static std::size_t sweep_blocks(std::size_t rows, std::size_t block_rows);

 private:
  // The matrices of one precision: levels[0] is the fine matrix (set_fine()), restriction[l] is
  // P_l^T, built once per hierarchy (restriction row by row).
  template <class Value>
  struct Hierarchy {
    std::vector<CsrOf<Value>> levels, interpolation, restriction;
  };
  template <class Value>
  const Hierarchy<Value>& hierarchy() const {
    if constexpr (std::is_same_v<Value, float>)
      return single_;
    else
      return exact_;
  }
  template <class Value>
  void cycle(std::size_t level, const double* b, double* x);
  // One Gauss-Seidel sweep: down, forward from x = 0 (x's values are not read); up, backward
  // from x. old: room for x before the sweep (the other blocks' values).
  template <class Value>
  void sweep(const CsrOf<Value>& A, const double* b, double* x, bool down,
             std::vector<double>& old);

  CyclePrecision precision_ = CyclePrecision::double_precision;
  Hierarchy<double> exact_;
  Hierarchy<float> single_;  // the same structure, values rounded (single precision only)
  // Storage behind the views: P^T's structure and values, the rounded values.
  std::vector<std::vector<int>> restriction_start_, restriction_column_;
  std::vector<std::vector<double>> restriction_value_;
  std::vector<std::vector<float>> single_levels_, single_interpolation_, single_restriction_;
  std::vector<float> single_fine_;
  std::vector<std::vector<double>> residual_, coarse_b_, coarse_x_, before_;
  Eigen::PartialPivLU<Eigen::MatrixXd> coarsest_;
  std::size_t block_rows_ = kDefaultBlockRows;
};

}  // namespace washout
