#pragma once
// A byte flag that several threads may set at once, all to 1 (a wall particle seen by many fluid
// particles, a region anchored by many rows): written through an atomic reference so that the
// concurrent writes are defined, and read first so that a line already marked stays unshared.
#include <atomic>
#include <cstdint>

namespace washout {

inline void mark_shared(std::uint8_t& flag) {
  std::atomic_ref<std::uint8_t> mark(flag);
  if (!mark.load(std::memory_order_relaxed)) mark.store(1, std::memory_order_relaxed);
}

}  // namespace washout
