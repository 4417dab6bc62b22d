#include "engine/solvers/cholesky_factor_solve.hpp"

#include <algorithm>

namespace washout {

CholeskyFactorSolve::Columns CholeskyFactorSolve::columns() const {
  const auto& L = factor_->matrixL().nestedExpression();  // compressed columns, diagonal first
  return {L.cols(), L.outerIndexPtr(), L.innerIndexPtr(), L.valuePtr()};
}

namespace {

// Below this many entries in L the solve stays whole and on one thread: a fork costs about a
// microsecond, and the 3D a/20 coarse solve takes some tens.
constexpr std::int64_t kCutEntries = 32768;
// A cut is kept where it brings the longer path (the top and the heavier group) under this share
// of the whole factor's work.
constexpr double kWorthwhileCut = 0.8;

}  // namespace

std::vector<std::int8_t> CholeskyFactorSolve::cut_tree(const Columns& L) {
  const std::int64_t n = L.n, total = L.start[n];
  std::vector<std::int8_t> owner(static_cast<std::size_t>(n), kTop);
  group_entries_ = {0, 0};
  top_entries_ = static_cast<std::size_t>(total);
  if (total < kCutEntries) return owner;
  // The elimination tree: parent(j) is column j's first row below the diagonal. Parents come
  // after their children, so one pass upwards sums each subtree's entries, size and first column.
  const auto entries = [&](std::int64_t j) { return L.start[j + 1] - L.start[j]; };
  std::vector<std::int64_t> parent(n), work(n), size(n, 1), first(n);
  std::vector<std::int64_t> child_start(n + 1, 0);
  for (std::int64_t j = 0; j < n; ++j) {
    parent[j] = entries(j) > 1 ? L.row[L.start[j] + 1] : -1;
    work[j] = entries(j);
    first[j] = j;
    if (parent[j] >= 0) ++child_start[parent[j] + 1];
  }
  for (std::int64_t j = 0; j < n; ++j) {
    if (parent[j] < 0) continue;
    work[parent[j]] += work[j];
    size[parent[j]] += size[j];
    first[parent[j]] = std::min(first[parent[j]], first[j]);
  }
  for (std::int64_t j = 0; j < n; ++j) child_start[j + 1] += child_start[j];
  std::vector<std::int64_t> child(static_cast<std::size_t>(child_start[n]));
  {
    std::vector<std::int64_t> slot(child_start.begin(), child_start.end() - 1);
    for (std::int64_t j = 0; j < n; ++j)
      if (parent[j] >= 0) child[slot[parent[j]]++] = j;
  }
  // A subtree a group can take as a run of columns (the orderings' post-order makes most so).
  const auto contiguous = [&](std::int64_t j) { return j - first[j] + 1 == size[j]; };

  // From the roots down: the heaviest subtree is cut off (its root joins the top, its children
  // become subtrees) while that can shorten the longer path, the top's work plus the heavier
  // group's, the subtrees shared out heaviest first to the lighter group.
  std::vector<std::int64_t> subtrees;
  for (std::int64_t j = 0; j < n; ++j)
    if (parent[j] < 0) subtrees.push_back(j);
  std::int64_t top = 0, best_path = total;
  std::vector<std::int64_t> best_subtrees;
  std::vector<std::int8_t> best_group;
  std::vector<std::int64_t> order;
  while (!subtrees.empty()) {
    if (std::all_of(subtrees.begin(), subtrees.end(), contiguous)) {
      order = subtrees;
      std::sort(order.begin(), order.end(), [&](std::int64_t a, std::int64_t b) {
        return work[a] != work[b] ? work[a] > work[b] : a < b;
      });
      std::int64_t load[2] = {0, 0};
      std::vector<std::int8_t> group(order.size());
      for (std::size_t k = 0; k < order.size(); ++k) {
        group[k] = load[1] < load[0] ? 1 : 0;
        load[group[k]] += work[order[k]];
      }
      const std::int64_t path = top + std::max(load[0], load[1]);
      if (path < best_path) {
        best_path = path;
        best_subtrees = order;
        best_group = group;
      }
    }
    // The next to cut: a subtree that is not a run of columns, else the heaviest.
    std::size_t next = 0;
    for (std::size_t k = 1; k < subtrees.size(); ++k) {
      const std::int64_t a = subtrees[k], b = subtrees[next];
      if (contiguous(a) != contiguous(b) ? !contiguous(a) : work[a] > work[b]) next = k;
    }
    const std::int64_t root = subtrees[next];
    top += entries(root);
    if (top >= best_path) break;  // no later cut can do better
    subtrees.erase(subtrees.begin() + static_cast<std::ptrdiff_t>(next));
    subtrees.insert(subtrees.end(), child.begin() + child_start[root],
                    child.begin() + child_start[root + 1]);
  }
  if (static_cast<double>(best_path) > kWorthwhileCut * static_cast<double>(total)) return owner;
  for (std::size_t k = 0; k < best_subtrees.size(); ++k) {
    const std::int64_t root = best_subtrees[k];
    std::fill(owner.begin() + first[root], owner.begin() + root + 1, best_group[k]);
    group_entries_[best_group[k]] += static_cast<std::size_t>(work[root]);
  }
  top_entries_ -= group_entries_[0] + group_entries_[1];
  return owner;
}

void CholeskyFactorSolve::build(const Factor& factor) {
  factor_ = &factor;
  const Columns L = columns();
  const std::vector<std::int8_t> owner = cut_tree(L);
  // Column j + 1 continues column j's supernode when column j's rows are j, j + 1 and then
  // exactly column j + 1's rows below its diagonal: by induction every column of a supernode
  // j..e-1 holds the rows from itself to e - 1 and then the last column's rows below. A
  // supernode stays within its group or the top.
  const auto continues = [&](std::int64_t j) {
    const std::int64_t a = L.start[j], b = L.start[j + 1];
    if (owner[j] != owner[j + 1]) return false;
    if (b - a != L.start[j + 2] - b + 1 || L.row[a + 1] != j + 1) return false;
    return std::equal(L.row + a + 2, L.row + b, L.row + b + 1);
  };
  node_start_.assign(1, 0);
  std::size_t longest = 0;  // no supernode has more rows below it than the longest column
  for (std::int64_t j = 0; j < L.n; ++j) {
    longest = std::max(longest, static_cast<std::size_t>(L.start[j + 1] - L.start[j]));
    if (j + 1 == L.n || !continues(j)) node_start_.push_back(static_cast<std::int32_t>(j + 1));
  }
  // Each supernode to its group or the top. A group's rows below a supernode are its subtree's
  // ancestors: first those in the subtree, then (all after the subtree's root) the top's.
  const std::size_t nodes = node_start_.size() - 1;
  own_below_.resize(nodes);
  top_nodes_.clear();
  for (auto& list : group_nodes_) list.clear();
  for (std::size_t k = 0; k < nodes; ++k) {
    const std::int64_t s = node_start_[k], e = node_start_[k + 1];
    const int* rows = L.row + L.start[e - 1] + 1;
    const std::int64_t below = L.start[e] - L.start[e - 1] - 1;
    const std::int8_t group = owner[s];
    std::int64_t own = below;
    if (group == kTop) {
      top_nodes_.push_back(static_cast<std::int32_t>(k));
    } else {
      group_nodes_[group].push_back(static_cast<std::int32_t>(k));
      own = std::find_if(rows, rows + below, [&](int r) { return owner[r] == kTop; }) - rows;
    }
    own_below_[k] = own;
  }
  for (int g = 0; g < 2; ++g) {
    below_[g].resize(longest);
    top_part_[g].assign(static_cast<std::size_t>(L.n), 0.0);
  }
  parallel_ = !group_nodes_[0].empty() && !group_nodes_[1].empty();
  // Multiplied by, not divided: the solves' chains wait for each column's result, and a
  // division takes several times a multiplication's latency.
  inverse_diagonal_.resize(static_cast<std::size_t>(L.n));
  for (std::int64_t j = 0; j < L.n; ++j) inverse_diagonal_[j] = 1.0 / L.value[L.start[j]];
}

std::size_t CholeskyFactorSolve::widest_supernode() const {
  std::size_t widest = 0;
  for (std::size_t k = 0; k + 1 < node_start_.size(); ++k)
    widest = std::max(widest, static_cast<std::size_t>(node_start_[k + 1] - node_start_[k]));
  return widest;
}

namespace {

constexpr std::int64_t kPanel = 4;  // columns taken together in the dense blocks

// out[r] -= sum_c column[c][r] y[c] over `count` (<= kPanel) columns: four columns a pass, so
// that each load and store of out serves four products.
void subtract_columns(const double* const* column, const double* y, std::int64_t count, double* out,
                      std::int64_t length) {
  if (count == kPanel) {
    const double *c0 = column[0], *c1 = column[1], *c2 = column[2], *c3 = column[3];
    const double y0 = y[0], y1 = y[1], y2 = y[2], y3 = y[3];
#pragma omp simd
    for (std::int64_t r = 0; r < length; ++r)
      out[r] -= (c0[r] * y0 + c1[r] * y1) + (c2[r] * y2 + c3[r] * y3);
    return;
  }
  for (std::int64_t c = 0; c < count; ++c) {
    const double* cc = column[c];
    const double yc = y[c];
#pragma omp simd
    for (std::int64_t r = 0; r < length; ++r) out[r] -= cc[r] * yc;
  }
}

// dot[c] = sum_r column[c][r] v[r] over `count` (<= kPanel) columns: four independent sums
// sharing each load of v.
void dot_columns(const double* const* column, std::int64_t count, const double* v,
                 std::int64_t length, double* dot) {
  if (count == kPanel) {
    const double *c0 = column[0], *c1 = column[1], *c2 = column[2], *c3 = column[3];
    double d0 = 0.0, d1 = 0.0, d2 = 0.0, d3 = 0.0;
#pragma omp simd reduction(+ : d0, d1, d2, d3)
    for (std::int64_t r = 0; r < length; ++r) {
      const double g = v[r];
      d0 += c0[r] * g;
      d1 += c1[r] * g;
      d2 += c2[r] * g;
      d3 += c3[r] * g;
    }
    dot[0] = d0, dot[1] = d1, dot[2] = d2, dot[3] = d3;
    return;
  }
  for (std::int64_t c = 0; c < count; ++c) {
    const double* cc = column[c];
    double d = 0.0;
#pragma omp simd reduction(+ : d)
    for (std::int64_t r = 0; r < length; ++r) d += cc[r] * v[r];
    dot[c] = d;
  }
}

}  // namespace

// L y = b, a supernode at a time and within it a panel of kPanel columns at a time: the panel's
// own small triangle, then its columns subtracted from the block's later rows and from the rows
// below the block (gathered, updated, scattered back; the top's rows below a group's supernode
// from and to top_part).
void CholeskyFactorSolve::forward(const Columns& L, const std::vector<std::int32_t>& nodes,
                                  double* top_part, double* gathered) {
  double* x = work_.data();
  const double* column[kPanel];
  for (const std::int32_t k : nodes) {
    const std::int64_t s = node_start_[k], e = node_start_[k + 1];
    const std::int64_t below = L.start[e] - L.start[e - 1] - 1, own = own_below_[k];
    const int* rows = L.row + L.start[e - 1] + 1;
    for (std::int64_t r = 0; r < own; ++r) gathered[r] = x[rows[r]];
    for (std::int64_t r = own; r < below; ++r) gathered[r] = top_part[rows[r]];
    for (std::int64_t ps = s; ps < e; ps += kPanel) {
      const std::int64_t pe = std::min(ps + kPanel, e), count = pe - ps;
      for (std::int64_t j = ps; j < pe; ++j) {
        const double* diagonal = entries_from(L, j, 0);
        x[j] *= inverse_diagonal_[j];
        for (std::int64_t i = j + 1; i < pe; ++i) x[i] -= x[j] * diagonal[i - j];
      }
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, pe - ps - c);
      subtract_columns(column, x + ps, count, x + pe, e - pe);
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, e - ps - c);
      subtract_columns(column, x + ps, count, gathered, below);
    }
    for (std::int64_t r = 0; r < own; ++r) x[rows[r]] = gathered[r];
    for (std::int64_t r = own; r < below; ++r) top_part[rows[r]] = gathered[r];
  }
}

// L^T x = y, the supernodes from the last: the rows below a supernode are final, their x
// gathered once and dotted with its columns; then its diagonal block a panel at a time from
// its last column, the rows after the panel dotted with the panel's columns before the panel's
// small triangle.
void CholeskyFactorSolve::backward(const Columns& L, const std::vector<std::int32_t>& nodes,
                                   double* gathered) {
  double* x = work_.data();
  const double* column[kPanel];
  double dot[kPanel];
  for (auto node = nodes.rbegin(); node != nodes.rend(); ++node) {
    const std::int32_t k = *node;
    const std::int64_t s = node_start_[k], e = node_start_[k + 1];
    const std::int64_t below = L.start[e] - L.start[e - 1] - 1;
    const int* rows = L.row + L.start[e - 1] + 1;
    for (std::int64_t r = 0; r < below; ++r) gathered[r] = x[rows[r]];
    for (std::int64_t pe = e; pe > s;) {
      const std::int64_t ps = std::max(pe - kPanel, s), count = pe - ps;
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, e - ps - c);
      dot_columns(column, count, gathered, below, dot);
      for (std::int64_t c = 0; c < count; ++c) x[ps + c] -= dot[c];
      for (std::int64_t c = 0; c < count; ++c) column[c] = entries_from(L, ps + c, pe - ps - c);
      dot_columns(column, count, x + pe, e - pe, dot);
      for (std::int64_t c = 0; c < count; ++c) x[ps + c] -= dot[c];
      for (std::int64_t j = pe - 1; j >= ps; --j) {
        const double* diagonal = entries_from(L, j, 0);
        double sum = x[j];
        for (std::int64_t i = j + 1; i < pe; ++i) sum -= diagonal[i - j] * x[i];
        x[j] = sum * inverse_diagonal_[j];
      }
      pe = ps;
    }
  }
}

void CholeskyFactorSolve::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const Columns L = columns();
  work_ = factor_->permutationP() * b;
  double* y = work_.data();
  const bool cut = !group_nodes_[0].empty() || !group_nodes_[1].empty();
  if (cut) {
#pragma omp parallel for num_threads(2) schedule(static, 1) if (parallel_)
    for (int g = 0; g < 2; ++g) forward(L, group_nodes_[g], top_part_[g].data(), below_[g].data());
    for (const std::int32_t k : top_nodes_)  // in group order, then cleared for the next
      for (std::int64_t j = node_start_[k]; j < node_start_[k + 1]; ++j) {
        y[j] += top_part_[0][j];
        y[j] += top_part_[1][j];
        top_part_[0][j] = top_part_[1][j] = 0.0;
      }
  }
  forward(L, top_nodes_, nullptr, below_[0].data());
  backward(L, top_nodes_, below_[0].data());
  if (cut) {
#pragma omp parallel for num_threads(2) schedule(static, 1) if (parallel_)
    for (int g = 0; g < 2; ++g) backward(L, group_nodes_[g], below_[g].data());
  }
  x = factor_->permutationPinv() * work_;
}

}  // namespace washout
