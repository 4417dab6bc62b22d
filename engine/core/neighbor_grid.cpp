#include "engine/core/neighbor_grid.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/core/vector_growth.hpp"

namespace washout {
namespace {

// Below this a sort is not worth forking for.
constexpr std::size_t kParallelSortParticles = 20000;

}  // namespace

long NeighborGrid::cell_coordinate(double x, int axis) const {
  long c = static_cast<long>(std::floor((x - origin_[axis]) / cell_size_[axis]));
  if (periodic_.periodic[axis]) return (c % cells_[axis] + cells_[axis]) % cells_[axis];
  return std::clamp(c, 0L, cells_[axis] - 1);
}

std::size_t NeighborGrid::cell_index(const long c[3]) const {
  return static_cast<std::size_t>(c[0]) +
         static_cast<std::size_t>(cells_[0]) *
             (static_cast<std::size_t>(c[1]) + static_cast<std::size_t>(cells_[1]) * c[2]);
}

void NeighborGrid::build(const Particles& particles, double radius, const PeriodicBox& periodic) {
  const double cell_size = radius / static_cast<double>(kReach);
  dim_ = particles.dim;
  periodic_ = periodic;
  const std::size_t n = particles.size();
  for (int a = 0; a < 3; ++a) {
    cells_[a] = 1;
    origin_[a] = 0.0;
    cell_size_[a] = cell_size;
    if (a >= dim_) continue;
    if (periodic.periodic[a]) {
      cells_[a] = static_cast<long>(std::floor(periodic.length[a] / cell_size));
      // Three supports: no cell is then reached twice by a search that wraps around.
      if (periodic.length[a] < 3.0 * radius)
        throw std::invalid_argument("periodic length along axis " + std::to_string(a) +
                                    " must be at least three kernel supports (3 x 2h)");
      cell_size_[a] = periodic.length[a] / cells_[a];
      origin_[a] = periodic.lower[a];
      continue;
    }
    double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
    const double* x = particles.position[a].data();
#pragma omp parallel for reduction(min : lo) reduction(max : hi)
    for (std::size_t i = 0; i < n; ++i) {
      if (particles.retired(i)) continue;
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
    }
    if (lo > hi) lo = hi = 0.0;  // no particle takes part
    origin_[a] = lo - 0.5 * cell_size;
    cells_[a] = static_cast<long>(std::floor((hi - origin_[a]) / cell_size)) + 2;
  }
  const std::size_t cell_count =
      static_cast<std::size_t>(cells_[0]) * static_cast<std::size_t>(cells_[1]) * cells_[2];
  if (cell_count > (std::size_t{1} << 31))
    throw std::runtime_error("neighbour grid too large: particles spread far beyond the domain");

  // Retired particles are in no cell: nobody finds them and they find nobody.
  const auto outside = static_cast<std::uint32_t>(cell_count);
  cell_of_.resize(n);
#pragma omp parallel for
  for (std::size_t i = 0; i < n; ++i) {
    if (particles.retired(i)) {
      cell_of_[i] = outside;
      continue;
    }
    long c[3] = {0, 0, 0};
    for (int a = 0; a < dim_; ++a) c[a] = cell_coordinate(particles.position[a][i], a);
    cell_of_[i] = static_cast<std::uint32_t>(cell_index(c));
  }
  // Counting sort by cell: particles of one cell are contiguous in sorted_, in index order (so
  // lists come out the same whatever the threads). On all threads: each counts its own range of
  // indices per cell; a cell's slots go to the ranges in order, so each range fills its share of
  // the cell in index order. (On one thread the sort took 0.7 s of the 3D a/40 same case while
  // the other thread waited, docs/performance.md, forty-third session.)
  const std::size_t buckets = cell_count + 1;  // the last: the retired
  cell_start_.resize(cell_count + 2);
  sorted_.resize(n);
#pragma omp parallel if (n > kParallelSortParticles)
  {
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
    {
      range_count_.resize(threads);
      range_total_.resize(threads);
    }
    std::vector<std::uint32_t>& count = range_count_[t];
    count.assign(buckets, 0);
    const std::size_t first = n * t / threads, last = n * (t + 1) / threads;
    for (std::size_t i = first; i < last; ++i) ++count[cell_of_[i]];
#pragma omp barrier
    // Each cell's start, the cells shared between the threads by range: the ranges' totals, then
    // within each range the cells' starts and each index range's first slot in the cell.
    const std::size_t cells_first = buckets * t / threads, cells_last = buckets * (t + 1) / threads;
    std::uint32_t total = 0;
    for (std::size_t c = cells_first; c < cells_last; ++c)
      for (std::size_t u = 0; u < threads; ++u) total += range_count_[u][c];
    range_total_[t] = total;
#pragma omp barrier
    std::uint32_t slot = 0;
    for (std::size_t u = 0; u < t; ++u) slot += range_total_[u];
    for (std::size_t c = cells_first; c < cells_last; ++c) {
      cell_start_[c] = slot;
      for (std::size_t u = 0; u < threads; ++u) {
        const std::uint32_t in_range = range_count_[u][c];
        range_count_[u][c] = slot;
        slot += in_range;
      }
    }
#pragma omp barrier
    for (std::size_t i = first; i < last; ++i)
      sorted_[count[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }
  cell_start_[cell_count + 1] = static_cast<std::uint32_t>(n);
  sorted_.resize(cell_start_[cell_count]);  // the retired, sorted last, are dropped
  // The positions in the same order: a search then reads the cells around a point as
  // contiguous memory instead of gathering three coordinates per candidate from anywhere.
  for (auto& x : sorted_position_) x.resize(sorted_.size());
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < sorted_.size(); ++k)
    for (int a = 0; a < 3; ++a) sorted_position_[a][k] = particles.position[a][sorted_[k]];
}

std::size_t NeighborGrid::collect_below(const Particles& particles, const double p[3],
                                        std::uint32_t limit, double radius2,
                                        std::vector<std::uint32_t>& found) const {
  // The particles' own positions, not build()'s copies: callers search after the fluid has
  // moved within a step (the probes, the push-out), from the cells it was bucketed in.
  const double* X = particles.position[0].data();
  const double* Y = particles.position[1].data();
  const double* Z = particles.position[2].data();
  const std::uint32_t* sj = sorted_.data();
  const bool periodic = periodic_.any();
  // As build_list: every candidate written, the count advanced past the hits only (about a
  // quarter of the candidates, at random: a branch on each was mispredicted often). A wall
  // candidate is read as index 0's position and then not counted.
  std::size_t count = 0;
  for_each_cell_around(p, [&](std::uint32_t begin, std::uint32_t end) {
    if (found.size() < count + (end - begin)) found.resize(2 * (count + (end - begin)));
    std::uint32_t* out = found.data();
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t j = sj[k];
      const bool below = j < limit;
      const std::uint32_t read = below ? j : 0;
      double d[3] = {p[0] - X[read], p[1] - Y[read], p[2] - Z[read]};
      if (periodic) periodic_.minimum_image(d);
      out[count] = j;
      count += below & (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < radius2);
    }
  });
  return count;
}

void NeighborGrid::build_list(const Particles& particles, std::size_t query_count, double radius,
                              NeighborList& list) const {
  const double r2max = radius * radius;
  const auto& X = particles.position;
  const bool periodic = periodic_.any();
  const double* sx = sorted_position_[0].data();
  const double* sy = sorted_position_[1].data();
  const double* sz = sorted_position_[2].data();
  const std::uint32_t* sj = sorted_.data();
  // The particles must be where build() bucketed them: the candidates' positions are its copy.
  // A candidate is a neighbour when it lies within the radius and is not i itself.
  const auto inside = [&](std::size_t i, const double p[3], std::uint32_t k) {
    double d[3] = {p[0] - sx[k], p[1] - sy[k], p[2] - sz[k]};
    if (periodic) periodic_.minimum_image(d);
    return (sj[k] != i) & (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < r2max);
  };
  // One pass over the candidates (row_blocks.hpp; a count pass and a fill pass tested every
  // candidate twice: the neighbour stage of the 3D same-case dam break at a/20 took 1.4 s with
  // them, 1.1 s with one). Without periodic images the fill is free of branches per candidate
  // (about a quarter of the candidates are neighbours, at random: a branch on each was
  // mispredicted often): it writes every candidate and advances past the neighbours only.
  list.offset.assign(query_count + 1, 0);
  list_blocks_.fill(query_count, [&](std::size_t first, std::size_t last, auto& out) {
    for (std::size_t i = first; i < last; ++i) {
      if (particles.retired(i)) continue;
      const double p[3] = {X[0][i], X[1][i], X[2][i]};
      const std::size_t row_start = out.filled();
      for_each_cell_around(p, [&](std::uint32_t begin, std::uint32_t end) {
        std::uint32_t* row = out.reserve(end - begin);
        std::size_t c = 0;
        for (std::uint32_t k = begin; k < end; ++k) {
          row[c] = sj[k];
          c += inside(i, p, k);
        }
        out.advance(c);
      });
      list.offset[i + 1] = out.filled() - row_start;
    }
  });
  for (std::size_t i = 0; i < query_count; ++i) list.offset[i + 1] += list.offset[i];
  grow_to(list.index, list_blocks_.entries());
  list_blocks_.place([&](const std::uint32_t* from, std::size_t count, std::size_t to) {
    std::copy(from, from + count, list.index.begin() + static_cast<std::ptrdiff_t>(to));
  });
}

}  // namespace washout
