// A closed body of fluid (no free surface, no given pressure: a filled tank, a periodic
// channel) has a PPE whose solutions differ by a constant. Per connected region of the matrix
// (union-find over its pattern) that no row anchors, the right-hand side is made compatible
// (its mean removed) and the region's first row doubles its diagonal, a Dirichlet-like anchor
// that keeps that pressure near zero.
#include <omp.h>

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "engine/core/shared_mark.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {
namespace {

// Every root is the smallest row of its region (a union links the larger root under the
// smaller), whatever the order of the unions: so the regions, their roots and all that follows do
// not depend on how the unions are shared among threads.
struct UnionFind {
  std::vector<std::int32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  std::int32_t root(std::int32_t x) const {  // find without compression: safe to share
    while (parent[x] != x) x = parent[x];
    return x;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

// "Reached" is carried from the anchored rows along the pattern by sweeps in row order, forward
// and back (rows are sorted by cell, the longest axis slowest, so a sweep follows the flow).
// Each thread sweeps its own rows first, reading only their flags; the rows left are swept on one
// thread, reading all. False means "not shown", not "free": the union-find decides then.
bool every_row_reaches_an_anchor(const std::vector<std::uint8_t>& anchored_row,
                                 const CsrMatrix& A) {
  const std::size_t rows = A.rows;
  std::vector<std::uint8_t> reached(anchored_row.begin(), anchored_row.begin() + rows);
  const auto reach = [&](std::size_t r, std::size_t begin, std::size_t end) {
    if (reached[r]) return;
    for (std::int64_t k = A.row_start[r] + 1; k < A.row_start[r + 1]; ++k) {
      const auto c = static_cast<std::size_t>(A.column[k]);
      if (c >= begin && c < end && reached[c]) {
        reached[r] = 1;
        return;
      }
    }
  };
  std::size_t left = 0;
#pragma omp parallel reduction(+ : left)
  {
    const std::size_t threads = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t begin = rows * t / threads, end = rows * (t + 1) / threads;
    for (std::size_t r = begin; r < end; ++r) reach(r, begin, end);
    for (std::size_t r = end; r-- > begin;) reach(r, begin, end);
    for (std::size_t r = begin; r < end; ++r) left += !reached[r];
  }
  for (int sweep = 0; sweep < 2 && left > 0; ++sweep) {
    left = 0;
    for (std::size_t r = 0; r < rows; ++r) reach(r, 0, rows);
    for (std::size_t r = rows; r-- > 0;) {
      reach(r, 0, rows);
      left += !reached[r];
    }
  }
  return left == 0;
}

std::size_t fix_free_pressure_levels(const std::vector<std::uint8_t>& anchored_row, CsrMatrix& A,
                                     std::vector<double>& rhs, std::vector<double>& second_rhs) {
  const std::size_t rows = A.rows;
  // Most steps have a free surface in every region: then nothing is left to fix, and the sweeps
  // show it at a fraction of the union-find's cost (which was 2.5 % of the same-case 3D dam break
  // at a/20).
  if (every_row_reaches_an_anchor(anchored_row, A)) return 0;
  UnionFind components(rows);
  // The pattern is symmetric (neighbourhood is): the entries above the diagonal hold every edge.
  // Each thread unites the edges within its own rows, whose parents stay among them (a parent is
  // never a larger row), and keeps the edges that leave them (a band at each cut, a few per cent)
  // for one thread to unite afterwards. Serial, this pass was about 1.5 % of a step.
  std::vector<std::vector<std::pair<std::int32_t, std::int32_t>>> crossing;
#pragma omp parallel
  {
#pragma omp single
    crossing.resize(static_cast<std::size_t>(omp_get_num_threads()));
    auto& mine = crossing[static_cast<std::size_t>(omp_get_thread_num())];
    const std::size_t threads = crossing.size(), t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t begin = rows * t / threads, end = rows * (t + 1) / threads;
    for (std::size_t r = begin; r < end; ++r)
      for (std::int64_t k = A.row_start[r] + 1; k < A.row_start[r + 1]; ++k) {
        const auto c = static_cast<std::size_t>(A.column[k]);
        if (c <= r) continue;
        if (c < end)
          components.unite(static_cast<std::int32_t>(r), static_cast<std::int32_t>(c));
        else
          mine.emplace_back(static_cast<std::int32_t>(r), static_cast<std::int32_t>(c));
      }
  }
  for (const auto& edges : crossing)
    for (const auto& [a, b] : edges) components.unite(a, b);
  std::vector<std::int32_t> root_of(rows);
#pragma omp parallel for schedule(static)
  for (std::size_t r = 0; r < rows; ++r) root_of[r] = components.root(static_cast<std::int32_t>(r));

  // A region is anchored if any of its rows is (threads may mark the same root).
  std::vector<std::uint8_t> anchored(rows, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t r = 0; r < rows; ++r) {
    if (anchored_row[r]) mark_shared(anchored[root_of[r]]);
  }
  // Most steps have a free surface in every region: then nothing is left to fix.
  std::size_t free_regions = 0;
#pragma omp parallel for schedule(static) reduction(+ : free_regions)
  for (std::size_t r = 0; r < rows; ++r)
    free_regions += root_of[r] == static_cast<std::int32_t>(r) && !anchored[r];
  if (free_regions == 0) return 0;
  const bool second = !second_rhs.empty();
  std::vector<double> rhs_sum(rows, 0.0), second_sum(second ? rows : 0, 0.0);
  std::vector<std::int64_t> size(rows, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    const auto root = root_of[r];
    if (anchored[root]) continue;
    rhs_sum[root] += rhs[r];
    if (second) second_sum[root] += second_rhs[r];
    ++size[root];
  }
  std::size_t fixed = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    const auto root = root_of[r];
    if (anchored[root]) continue;
    rhs[r] -= rhs_sum[root] / size[root];
    if (second) second_rhs[r] -= second_sum[root] / size[root];
    if (static_cast<std::size_t>(root) == r) {
      A.value[A.row_start[r]] *= 2.0;
      ++fixed;
    }
  }
  return fixed;
}

}  // namespace washout
