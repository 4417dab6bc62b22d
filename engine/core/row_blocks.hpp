#pragma once
// Compressed rows (the neighbour list) built in one parallel pass over their data. The rows are
// dealt in blocks of kRowsPerBlock, block b to thread b % threads (a static schedule of one
// block at a time); each thread appends its blocks' entries to its own buffer, and the caller
// records the row lengths. Once the lengths are known, each block's entries are copied to their
// place, which is the sum of the blocks before it. A count pass and
// a fill pass would take every row's data twice; this takes it once and copies the entries,
// and the result is the same whatever the number of threads. The buffers are kept from build to
// build: no allocation and no first touch of memory in a time step once they have grown.
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "engine/core/vector_growth.hpp"

namespace washout {

template <class Entry>
class RowBlocks {
 public:
  static constexpr std::size_t kRowsPerBlock = 512;

  // fill(first, last, out) appends the entries of rows [first, last) through out (RowAppender)
  // and records the rows' lengths where the caller keeps them.
  template <class Fill>
  void fill(std::size_t rows, Fill&& fill);

  // The entries filled, all blocks together.
  std::size_t entries() const { return destination_.empty() ? 0 : destination_.back(); }

  // place(from, count, to) moves count entries from `from` to the output's positions
  // [to, to + count), for every block.
  template <class Place>
  void place(Place&& place);

  // Room for `count` more entries after the `filled` ones of one thread's buffer.
  class RowAppender {
   public:
    Entry* reserve(std::size_t count) {
      // A quarter more than asked: a few growths in a run's first steps, and little memory held
      // beyond the list itself (doubling held up to twice it: 400 MB at 2.6 M particles).
      if (buffer_.size() < filled_ + count) grow_to(buffer_, (filled_ + count) * 5 / 4 + 64);
      return buffer_.data() + filled_;
    }
    void advance(std::size_t count) { filled_ += count; }  // the reserved entries now written
    std::size_t filled() const { return filled_; }

   private:
    friend class RowBlocks;
    RowAppender(std::vector<Entry>& buffer, std::size_t filled)
        : buffer_(buffer), filled_(filled) {}
    std::vector<Entry>& buffer_;
    std::size_t filled_;
  };

 private:
  std::vector<std::vector<Entry>> buffers_;  // one per thread
  std::vector<std::size_t> start_, length_;  // block b: first entry in its thread's buffer, count
  std::vector<std::size_t> destination_;     // [blocks + 1]: block b's first entry in the output
  int threads_ = 1;
};

template <class Entry>
template <class Fill>
void RowBlocks<Entry>::fill(std::size_t rows, Fill&& fill) {
  const std::size_t blocks = (rows + kRowsPerBlock - 1) / kRowsPerBlock;
  start_.assign(blocks, 0);
  length_.assign(blocks, 0);
  buffers_.resize(std::max<std::size_t>(buffers_.size(), omp_get_max_threads()));
#pragma omp parallel
  {
#pragma omp single
    threads_ = omp_get_num_threads();
    RowAppender out(buffers_[omp_get_thread_num()], 0);
#pragma omp for schedule(static, 1)
    for (std::size_t b = 0; b < blocks; ++b) {
      start_[b] = out.filled();
      fill(b * kRowsPerBlock, std::min(rows, (b + 1) * kRowsPerBlock), out);
      length_[b] = out.filled() - start_[b];
    }
  }
  destination_.assign(blocks + 1, 0);
  for (std::size_t b = 0; b < blocks; ++b) destination_[b + 1] = destination_[b] + length_[b];
}

template <class Entry>
template <class Place>
void RowBlocks<Entry>::place(Place&& place) {
  // The same deal of blocks to threads as fill()'s: block b is in buffer b % threads.
#pragma omp parallel for schedule(static, 1) num_threads(threads_)
  for (std::size_t b = 0; b < length_.size(); ++b)
    place(buffers_[b % static_cast<std::size_t>(threads_)].data() + start_[b], length_[b],
          destination_[b]);
}

}  // namespace washout
