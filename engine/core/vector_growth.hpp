#pragma once
// Growing a run's large arrays by a little, not by double. Debian's hypre loads SuperLU_DIST,
// whose start-up code turns off glibc's mmap for large blocks and the trimming of the heap
// (mallopt(M_MMAP_MAX, 0) and mallopt(M_TRIM_THRESHOLD, -1)), so no block a run frees is given
// back to the system: it stays resident until a later allocation reuses it. std::vector grows by
// doubling its capacity and freeing the old block, and at the paper's resolution the PPE matrix
// (600 MB) growing by 372 entries at step 19 raised the peak memory by 570 MB
// (docs/performance.md, twenty-seventh session). grow_to() reserves an eighth more than asked
// when the capacity runs out, and never shrinks.
#include <cstddef>
#include <vector>

namespace washout {

template <class T>
void grow_to(std::vector<T>& v, std::size_t size) {
  if (size > v.capacity()) v.reserve(size + size / 8);
  v.resize(size);
}

}  // namespace washout
