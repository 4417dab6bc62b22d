#include "engine/solvers/symmetric_product.hpp"

#include <algorithm>

namespace washout {
namespace {

// Blocks of at least 1,024 rows and at most 64 of them: enough for the threads of a workstation,
// few enough that the buffers' reach beyond them (a band each) stays a small share of the matrix.
constexpr std::size_t kMinBlockRows = 1024, kMaxBlocks = 64;
// As for the full rows (sparse_matrix.cpp): below this a product is not worth forking for.
constexpr std::size_t kParallelNonzeros = 100000;

}  // namespace

void SymmetricProduct::clear() {
  rows_ = block_rows_ = blocks_ = 0;
  diagonal_.clear();
  start_.clear();
  column_.clear();
  value_.clear();
  buffer_start_.clear();
  buffer_.clear();
}

bool SymmetricProduct::build(const CsrMatrix& A) {
  // Sized, never cleared: a vector resized from empty writes zeros over all of it, on one
  // thread, before the fill below writes every entry again (2 s of serial memset in the 3D
  // a/40 same case, one build a solve). Resized from the last build's size, only a longer
  // tail is zeroed.
  rows_ = block_rows_ = blocks_ = 0;
  const std::size_t n = A.rows;
  if (n == 0) {
    clear();
    return false;
  }
  const std::size_t block_rows = std::max(kMinBlockRows, (n + kMaxBlocks - 1) / kMaxBlocks);
  const std::size_t blocks = (n + block_rows - 1) / block_rows;
  const bool parallel = A.nonzeros() > kParallelNonzeros;

  diagonal_.resize(n);   // each row sets its own, in the fill below
  start_.resize(n + 1);  // each row sets its count, in the walk below
  start_[0] = 0;
  // One walk over the columns gives each row's upper count and each block's reach (the furthest
  // column its rows scatter to; its buffer spans its own rows and those up to its reach). Blocks
  // in the outer loop, so that a block's reach is one thread's. The values are read once, by
  // the fill below (read here for the diagonal alone, one line a row, they were 70 % of this
  // walk's time at a/40).
  buffer_start_.assign(blocks + 1, 0);
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t end = std::min(n, (b + 1) * block_rows);
    std::size_t reach = end;
    for (std::size_t i = b * block_rows; i < end; ++i) {
      std::int64_t upper = 0;
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k) {
        const auto j = static_cast<std::size_t>(A.column[k]);
        upper += j > i;
        reach = std::max(reach, j + 1);
      }
      start_[i + 1] = upper;
    }
    buffer_start_[b + 1] = static_cast<std::int64_t>(reach - b * block_rows);
  }
  for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
  for (std::size_t b = 0; b < blocks; ++b) buffer_start_[b + 1] += buffer_start_[b];
  const auto upper = static_cast<std::size_t>(start_[n]);
  // An entry beyond the blocks costs 16 bytes a product (cleared, read back), an upper entry
  // saves 12 against the full rows: declined where the former exceed half the latter. (The README
  // wash-out's system at 1.0 s, its numbering mixed by the flow past the pier: 0.28 of the upper
  // entries, 233 us a product in full rows, 196 us from the triangle, two threads.)
  if (2 * (static_cast<std::size_t>(buffer_start_[blocks]) - n) > upper)
    return false;  // not ready; the arrays keep their sizes for the next build

  column_.resize(upper);
  value_.resize(upper);
  // The upper entries in their rows' order, and the diagonal. The rows come from the neighbour
  // lists, their columns in no order, so "upper or not" is a coin toss per entry: every entry is
  // written and the slot advanced past the upper ones only (no branch to mispredict). A write
  // that is not kept lands on a slot that its own row or a later one of the block then writes;
  // past the block's last slot (the next block's, another thread's) it goes to a spare instead.
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t end = std::min(n, (b + 1) * block_rows);
    const std::int64_t limit = start_[end];
    std::int32_t spare_column = 0;
    double spare_value = 0.0;
    for (std::size_t i = b * block_rows; i < end; ++i) {
      std::int64_t slot = start_[i];
      double diagonal = 0.0;
      for (std::int64_t k = A.row_start[i]; k < A.row_start[i + 1]; ++k) {
        const auto j = static_cast<std::size_t>(A.column[k]);
        if (j == i) diagonal += A.value[k];
        const bool inside = slot < limit;
        (inside ? column_[static_cast<std::size_t>(slot)] : spare_column) = A.column[k];
        (inside ? value_[static_cast<std::size_t>(slot)] : spare_value) = A.value[k];
        slot += j > i;
      }
      diagonal_[i] = diagonal;
    }
  }
  // Each product clears its blocks' buffers before scattering into them.
  buffer_.resize(static_cast<std::size_t>(buffer_start_[blocks]));
  rows_ = n;
  block_rows_ = block_rows;
  blocks_ = blocks;
  parallel_ = parallel;
  return true;
}

void SymmetricProduct::multiply(const std::vector<double>& x, std::vector<double>& y) {
  const std::size_t n = rows_;
  y.resize(n);
#pragma omp parallel if (parallel_)
  {
    // Each block on its own, into its buffer: its rows' gathers, and the scatters into its own
    // rows and beyond them (one store per entry, no test of where it lands).
#pragma omp for schedule(static)
    for (std::size_t b = 0; b < blocks_; ++b) {
      const std::size_t begin = b * block_rows_, end = std::min(n, begin + block_rows_);
      const std::int64_t base = buffer_start_[b] - static_cast<std::int64_t>(begin);
      double* buffer = buffer_.data();
      std::fill(buffer + buffer_start_[b], buffer + buffer_start_[b + 1], 0.0);
      for (std::size_t i = begin; i < end; ++i) {
        const double x_i = x[i];
        double sum = buffer[base + static_cast<std::int64_t>(i)] + diagonal_[i] * x_i;
        for (std::int64_t k = start_[i]; k < start_[i + 1]; ++k) {
          const std::int32_t j = column_[k];
          sum += value_[k] * x[j];
          buffer[base + j] += value_[k] * x_i;
        }
        y[i] = sum;
      }
    }
    // The scatters beyond each block added to the rows they reach, each row taking them in
    // block order.
#pragma omp for schedule(static)
    for (std::size_t c = 1; c < blocks_; ++c) {
      const std::size_t begin = c * block_rows_, end = std::min(n, begin + block_rows_);
      for (std::size_t b = 0; b < c; ++b) {
        const std::size_t from = b * block_rows_;  // the first row of b's buffer
        const std::size_t reach =
            from + static_cast<std::size_t>(buffer_start_[b + 1] - buffer_start_[b]);
        const double* buffer = buffer_.data() + buffer_start_[b];
        for (std::size_t j = begin; j < std::min(end, reach); ++j) y[j] += buffer[j - from];
      }
    }
  }
}

double SymmetricProduct::product_bytes() const {
  const double n = double(rows_);
  // Upper entries and their columns once, row starts and the diagonal once, x read and y
  // written once, each buffer entry cleared and read back once.
  return double(value_.size()) * (sizeof(double) + sizeof(std::int32_t)) +
         (n + 1) * sizeof(std::int64_t) + 3.0 * n * sizeof(double) +
         2.0 * double(buffer_.size()) * sizeof(double);
}

}  // namespace washout
