// The pressure level of closed regions (engine/fluid/ppe_null_space.cpp) and the boundary
// particles the fluid sees (engine/boundary/virtual_markers.cpp): both walk every pair of a step
// on all threads, and both must give the same answer on any number of threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "engine/boundary/virtual_markers.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {
namespace {

// A symmetric pattern of `rows` rows from undirected edges, each row's diagonal first.
CsrMatrix from_edges(std::size_t rows, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> adjacent(rows);
  for (const auto& [a, b] : edges) {
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  CsrMatrix A;
  A.rows = rows;
  A.row_start.assign(rows + 1, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    A.column.push_back(static_cast<std::int32_t>(r));
    A.value.push_back(1.0 + double(adjacent[r].size()));
    for (int c : adjacent[r]) {
      A.column.push_back(c);
      A.value.push_back(-1.0);
    }
    A.row_start[r + 1] = static_cast<std::int64_t>(A.column.size());
  }
  return A;
}

struct Fixed {
  std::size_t regions = 0;
  std::vector<double> rhs, second, diagonal;  // second: 3 rhs + 1 before, made compatible too
};

Fixed fix_on_threads(int threads, CsrMatrix A, const std::vector<std::uint8_t>& anchored,
                     std::vector<double> rhs) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Fixed f;
  std::vector<double> second(rhs.size());
  for (std::size_t r = 0; r < rhs.size(); ++r) second[r] = 3.0 * rhs[r] + 1.0;
  f.regions = fix_free_pressure_levels(anchored, A, rhs, second);
  omp_set_num_threads(before);
  f.rhs = rhs;
  f.second = second;
  for (std::size_t r = 0; r < A.rows; ++r) f.diagonal.push_back(A.value[A.row_start[r]]);
  return f;
}

// Three regions whose edges cross every cut the threads could make: the even rows in one chain
// from 0 to 998, the odd rows below 500 in another, the odd rows above in a third, anchored at row
// 777. The two free regions (roots 0 and 1) get a right-hand side of zero mean and a doubled
// diagonal at their smallest row; the anchored one is left alone.
TEST(PpeNullSpace, ClosedRegionsAreFoundAlikeOnAnyNumberOfThreads) {
  const std::size_t rows = 1000;
  std::vector<std::pair<int, int>> edges;
  for (int r = 0; r + 2 < int(rows); r += 2) edges.emplace_back(r, r + 2);
  for (int r = 1; r + 2 < 500; r += 2) edges.emplace_back(r, r + 2);
  for (int r = 501; r + 2 < int(rows); r += 2) edges.emplace_back(r, r + 2);
  const CsrMatrix A = from_edges(rows, edges);
  std::vector<std::uint8_t> anchored(rows, 0);
  anchored[777] = 1;
  std::vector<double> rhs(rows);
  for (std::size_t r = 0; r < rows; ++r) rhs[r] = std::sin(0.37 * double(r)) + 0.25;

  const Fixed one = fix_on_threads(1, A, anchored, rhs);
  EXPECT_EQ(one.regions, 2u);
  const auto region_mean = [&](const Fixed& f, int first, int last) {
    double sum = 0.0;
    int count = 0;
    for (int r = first; r <= last; r += 2, ++count) sum += f.rhs[r];
    return sum / count;
  };
  EXPECT_NEAR(region_mean(one, 0, 998), 0.0, 1e-14);
  EXPECT_NEAR(region_mean(one, 1, 499), 0.0, 1e-14);
  for (int r = 501; r < int(rows); r += 2) EXPECT_EQ(one.rhs[r], rhs[r]) << r;
  // The second right-hand side (the density term's alone, density_kick.cpp) of the same regions:
  // made compatible in the free ones, 3 (rhs - its mean) there; left alone in the anchored one.
  for (int r = 0; r < int(rows); ++r) {
    const bool anchored_region = r % 2 == 1 && r > 500;
    EXPECT_NEAR(one.second[r], anchored_region ? 3.0 * rhs[r] + 1.0 : 3.0 * one.rhs[r], 1e-13) << r;
  }
  EXPECT_EQ(one.diagonal[0], 2.0 * A.value[A.row_start[0]]);
  EXPECT_EQ(one.diagonal[1], 2.0 * A.value[A.row_start[1]]);
  for (std::size_t r = 2; r < rows; ++r) EXPECT_EQ(one.diagonal[r], A.value[A.row_start[r]]) << r;
  std::printf("free regions found: %zu; their right-hand side means %.1e and %.1e\n", one.regions,
              region_mean(one, 0, 998), region_mean(one, 1, 499));

  for (int threads : {2, 3, 7}) {
    const Fixed many = fix_on_threads(threads, A, anchored, rhs);
    EXPECT_EQ(many.regions, one.regions) << threads << " threads";
    EXPECT_EQ(many.rhs, one.rhs) << threads << " threads";
    EXPECT_EQ(many.second, one.second) << threads << " threads";
    EXPECT_EQ(many.diagonal, one.diagonal) << threads << " threads";
  }
}

// The shortcut that skips the union-find where every row reaches an anchor: shown by the sweeps
// on a chain numbered in order (one anchor in the middle), on any number of threads; never
// claimed where a region is free; and where the chain winds back and forth through the
// numbering (0, 999, 1, 998, ...) so that sweeps do not get there, the union-find still finds
// nothing to fix.
TEST(PpeNullSpace, TheSweepsShortcutOnlyWhereEveryRowReachesAnAnchor) {
  const std::size_t rows = 1000;
  std::vector<std::pair<int, int>> in_order, winding;
  for (int r = 0; r + 1 < int(rows); ++r) in_order.emplace_back(r, r + 1);
  std::vector<int> path;
  for (int k = 0; k < int(rows) / 2; ++k) {
    path.push_back(k);
    path.push_back(int(rows) - 1 - k);
  }
  for (std::size_t k = 0; k + 1 < path.size(); ++k) winding.emplace_back(path[k], path[k + 1]);
  std::vector<std::uint8_t> anchored(rows, 0);
  anchored[777] = 1;
  const CsrMatrix chain = from_edges(rows, in_order), wound = from_edges(rows, winding);
  std::vector<double> rhs(rows);
  for (std::size_t r = 0; r < rows; ++r) rhs[r] = std::cos(0.21 * double(r));
  for (int threads : {1, 2, 3}) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    EXPECT_TRUE(every_row_reaches_an_anchor(anchored, chain)) << threads << " threads";
    EXPECT_FALSE(every_row_reaches_an_anchor(std::vector<std::uint8_t>(rows, 0), chain))
        << threads << " threads";
    // Anchored at one end of the winding chain: the far end is 999 rows away along it.
    std::vector<std::uint8_t> at_start(rows, 0);
    at_start[0] = 1;
    const bool shown = every_row_reaches_an_anchor(at_start, wound);
    omp_set_num_threads(before);
    const Fixed f = fix_on_threads(threads, wound, at_start, rhs);
    EXPECT_EQ(f.regions, 0u) << threads << " threads";
    EXPECT_EQ(f.rhs, rhs) << threads << " threads";
    std::printf("%d threads: the winding chain %s by the sweeps\n", threads,
                shown ? "shown anchored" : "left to the union-find");
  }
}

// Fluid particles 0-3, wall particles 4-9: the fluid sees walls 5, 7 and 9 (two of them from
// more than one fluid particle), and 4, 6, 8 are dry.
TEST(ActiveBoundary, MarksEveryWallParticleSomeFluidSeesOnAnyNumberOfThreads) {
  Particles p;
  for (int i = 0; i < 4; ++i) p.add(ParticleKind::Fluid, Vec3::Zero(), Vec3::Zero(), -1);
  for (int i = 0; i < 6; ++i) p.add(ParticleKind::FixedWall, Vec3::Zero(), Vec3::Zero(), 0);
  NeighborList list;
  list.offset = {0, 3, 5, 5, 8};
  list.index = {1, 5, 7, 0, 7, 9, 5, 2};
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    std::vector<std::uint8_t> active;
    EXPECT_EQ(mark_active_boundary(list, p, active), 3u) << threads << " threads";
    EXPECT_EQ(active, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 0, 1, 0, 1}))
        << threads << " threads";
  }
}

}  // namespace
}  // namespace washout
