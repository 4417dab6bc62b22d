// A closed body of fluid (no free surface, no given pressure: a filled tank, a periodic
// channel) has a PPE whose solutions differ by a constant. Per connected region of the matrix
// (union-find over its pattern) that no row anchors, the right-hand side is made compatible
// (its mean removed) and the region's first row doubles its diagonal, a Dirichlet-like anchor
// that keeps that pressure near zero.
#include <algorithm>
#include <numeric>

#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {
namespace {

struct UnionFind {
  std::vector<std::int32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

std::size_t fix_free_pressure_levels(const std::vector<std::uint8_t>& anchored_row, CsrMatrix& A,
                                     std::vector<double>& rhs) {
  const std::size_t rows = A.rows;
  UnionFind components(rows);
  // The pattern is symmetric (neighbourhood is): the entries above the diagonal hold every edge.
  for (std::size_t r = 0; r < rows; ++r)
    for (std::int64_t k = A.row_start[r] + 1; k < A.row_start[r + 1]; ++k)
      if (static_cast<std::size_t>(A.column[k]) > r)
        components.unite(static_cast<std::int32_t>(r), A.column[k]);
  std::vector<std::uint8_t> anchored(rows, 0);
  for (std::size_t r = 0; r < rows; ++r)
    if (anchored_row[r]) anchored[components.find(static_cast<std::int32_t>(r))] = 1;
  std::vector<double> rhs_sum(rows, 0.0);
  std::vector<std::int64_t> size(rows, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    const auto root = components.find(static_cast<std::int32_t>(r));
    if (anchored[root]) continue;
    rhs_sum[root] += rhs[r];
    ++size[root];
  }
  std::size_t fixed = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    const auto root = components.find(static_cast<std::int32_t>(r));
    if (anchored[root]) continue;
    rhs[r] -= rhs_sum[root] / size[root];
    if (static_cast<std::size_t>(root) == r) {
      A.value[A.row_start[r]] *= 2.0;
      ++fixed;
    }
  }
  return fixed;
}

}  // namespace washout
