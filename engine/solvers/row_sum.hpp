#pragma once
// sum_k value[k] x[column[k]] over one sparse row, in four interleaved partial sums. A single
// running sum makes every term wait for the previous addition (four cycles each): a 3D pressure
// row of about 50 terms then takes 200 cycles however fast the loads arrive, and where rows
// depend on each other (a Gauss-Seidel sweep) nothing overlaps that chain. Four sums cut it to a
// quarter. The order of the additions is fixed by the row alone, so a run's numbers do not
// depend on the threads (docs/performance.md, twenty-first session).
#include <cstdint>

namespace washout {

// x_at(j) gives the vector's value at column j (a sweep reads some columns from a copy). The
// values may be stored in single precision (a preconditioner's, threaded_vcycle.hpp); the sums
// are always in double.
template <class Value, class Index, class XAt>
inline double sparse_row_sum(const Value* value, const Index* column, std::int64_t begin,
                             std::int64_t end, XAt&& x_at) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::int64_t k = begin;
  for (; k + 4 <= end; k += 4) {
    s0 += double(value[k]) * x_at(column[k]);
    s1 += double(value[k + 1]) * x_at(column[k + 1]);
    s2 += double(value[k + 2]) * x_at(column[k + 2]);
    s3 += double(value[k + 3]) * x_at(column[k + 3]);
  }
  for (; k < end; ++k) s0 += double(value[k]) * x_at(column[k]);
  return (s0 + s1) + (s2 + s3);
}

template <class Value, class Index>
inline double sparse_row_dot(const Value* value, const Index* column, std::int64_t begin,
                             std::int64_t end, const double* x) {
  return sparse_row_sum(value, column, begin, end, [x](Index j) { return x[j]; });
}

}  // namespace washout
