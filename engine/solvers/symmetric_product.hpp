#pragma once
// y = A x for the symmetric pressure matrix, stored once: its diagonal and its upper triangle.
// Half the bytes of the full rows, and the product is bound by the bytes it moves (the 3D
// same-case dam break at a/20: 0.39 M non-zeros, 262-284 us a product on one thread in full
// rows, 149-161 us from the upper triangle; docs/performance.md, eighteenth session).
//
// Row i gathers its upper entries, sum_{j>i} a_ij x_j, and scatters their transposes,
// y_j += a_ij x_i. For threads, the rows are cut into fixed blocks (their size set by the
// matrix, never by the thread count, so a run gives the same numbers on one thread or two):
// a block scatters into a buffer of its own that spans its rows and those its scatters reach
// beyond them, and a second pass adds the part beyond to those rows in block order. A
// neighbour's row lies within a band of the particle's own (the particles are numbered along the
// lattice), so a buffer spans a block and a band, not the matrix; where the numbering has mixed
// so far that the buffers would cost more than the half saved, build() declines and the caller
// multiplies by the full rows. Jacobi CG (pcg) uses it; BoomerAMG CG (pcg_amg) keeps the full
// rows, which its set-up needs anyway (pcg_solver.cpp).
#include <cstdint>
#include <vector>

#include "engine/solvers/sparse_matrix.hpp"

namespace washout {

class SymmetricProduct {
 public:
  // Takes A's diagonal and upper triangle (A must be symmetric: its lower triangle is not read).
  // False, and not ready(), where the buffers' reach beyond their blocks would exceed half the
  // upper entries.
  bool build(const CsrMatrix& A);
  bool ready() const { return rows_ > 0; }
  void clear();

  void multiply(const std::vector<double>& x, std::vector<double>& y);  // y = A x
  // The least memory traffic of one product, as csr_product_bytes counts the full rows'.
  double product_bytes() const;
  std::size_t upper_entries() const { return ready() ? value_.size() : 0; }
  std::size_t spill_entries() const {  // beyond the blocks
    return ready() ? buffer_.size() - rows_ : 0;
  }

 private:
  std::size_t rows_ = 0, block_rows_ = 0, blocks_ = 0;
  bool parallel_ = false;
  std::vector<double> diagonal_;
  std::vector<std::int64_t> start_;  // [rows + 1] into column_ and value_
  std::vector<std::int32_t> column_;
  std::vector<double> value_;
  // Block b's buffer covers rows [begin_b, reach_b): buffer_[buffer_start_[b] + (j - begin_b)].
  std::vector<std::int64_t> buffer_start_;  // [blocks + 1]
  std::vector<double> buffer_;
};

}  // namespace washout
