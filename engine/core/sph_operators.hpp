#pragma once
// The SPH operators of METHOD.md ("SPH operators"), each under its own name, built on one
// neighbour-pair walk. A stage that needs an operator calls it with a function that gives the
// value a neighbour j carries: a fluid particle its own, a boundary particle its virtual-marker
// value (or i's own value, so that it adds nothing to a difference form). So every stage and
// every unit test sums the same terms in the same order.
//
//   gradient (difference)  <grad f>_i = sum_j V (f_j - f_i) grad W_ij
//   gradient (symmetric)   <grad f>_i = sum_j V (f_i + f_j) grad W_ij
//   divergence             <div u>_i  = sum_j V (u_j - u_i) . grad W_ij
//   laplacian              <lap f>_i  = sum_j V 2 (r_ij . grad W_ij) / (|r_ij|^2 + eta^2) (f_i -
//   f_j)
//
// with equal volumes V = m / rho0 (which is what keeps the PPE symmetric), so the symmetric
// gradient rho_i sum_j m_j (f_i/rho_i^2 + f_j/rho_j^2) grad W_ij reads as above, and with the
// lattice normalisation of SphContext (exact for linear gradients and quadratic laplacians on
// the initial lattice).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "engine/core/dimension.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"

namespace washout {

// One neighbour j of particle i: r_ij = x_i - x_j (periodic minimum image), |r_ij|^2, |r_ij|.
struct NeighborPair {
  std::size_t j;
  double d[3];
  double r2, r;
};

// Calls visit(pair) for every neighbour j of i, in the list's order.
// Always inlined into its caller: out of line, the caller's sums (a divergence, a row of the PPE)
// were reached through the visitor's references, and since any load of a double might read them
// the compiler stored each back to memory at every pair (store-to-load latency in every walk's
// chain; the predictor and the shifting of the 3D same-case dam break took 10-20 % longer).
template <class Visit>
[[gnu::always_inline]] inline void for_each_neighbor(const SphContext& ctx,
                                                     const NeighborList& list, const Particles& p,
                                                     std::size_t i, Visit&& visit) {
  const std::uint64_t begin = list.offset[i], end = list.offset[i + 1];
  if (ctx.periodic.any()) {
    for (std::uint64_t k = begin; k < end; ++k) {
      NeighborPair q;
      q.j = list.index[k];
      ctx.displacement(p, i, q.j, q.d);
      q.r2 = q.d[0] * q.d[0] + q.d[1] * q.d[1] + q.d[2] * q.d[2];
      q.r = std::sqrt(q.r2);
      visit(q);
    }
    return;
  }
  // The pairs' geometry first, a chunk at a time in a loop the compiler vectorises (gathers of
  // x_j, four square roots at once), then the visits: the square root's latency no longer sits
  // in each visit's chain.
  constexpr std::size_t kChunk = 64;
  alignas(64) double dx[kChunk], dy[kChunk], dz[kChunk], r2[kChunk], r[kChunk];
  const double* X = p.position[0].data();
  const double* Y = p.position[1].data();
  const double* Z = p.position[2].data();
  const double xi = X[i], yi = Y[i], zi = Z[i];
  for (std::uint64_t k0 = begin; k0 < end; k0 += kChunk) {
    const std::size_t m = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, end - k0));
    const std::uint32_t* index = list.index.data() + k0;
#pragma omp simd
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t j = index[k];
      dx[k] = xi - X[j];
      dy[k] = yi - Y[j];
      dz[k] = zi - Z[j];
      r2[k] = dx[k] * dx[k] + dy[k] * dy[k] + dz[k] * dz[k];
      r[k] = std::sqrt(r2[k]);
    }
    for (std::size_t k = 0; k < m; ++k) {
      NeighborPair q;
      q.j = index[k];
      q.d[0] = dx[k];
      q.d[1] = dy[k];
      q.d[2] = dz[k];
      q.r2 = r2[k];
      q.r = r[k];
      visit(q);
    }
  }
}

// sum_j factor(pair) r_ij over i's neighbours, into out: both gradients' shape. The sum stays in
// registers for the walk (with_dimension).
template <class PairFactor>
inline void sum_over_pairs(const SphContext& ctx, const NeighborList& list, const Particles& p,
                           std::size_t i, PairFactor&& factor, double out[3]) {
  with_dimension(ctx.dim, [&](auto dim) {
    double sum[3] = {0, 0, 0};
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      const double f = factor(q);
      for (int a = 0; a < dim; ++a) sum[a] += f * q.d[a];
    });
    for (int a = 0; a < 3; ++a) out[a] = sum[a];
  });
}

// <grad f>_i, difference form. value(pair) is f_j.
template <class Value>
inline void difference_gradient(const SphContext& ctx, const NeighborList& list, const Particles& p,
                                std::size_t i, double f_i, Value&& value, double grad[3]) {
  sum_over_pairs(
      ctx, list, p, i,
      [&](const NeighborPair& q) { return ctx.gradient_weight(q.r) * (value(q) - f_i); }, grad);
}

// <grad f>_i, symmetric (momentum-conserving) form. value(pair) is f_j; pair_scale(pair) a factor
// symmetric in i and j (the pair force stays antisymmetric).
template <class Value, class PairScale>
inline void symmetric_gradient(const SphContext& ctx, const NeighborList& list, const Particles& p,
                               std::size_t i, double f_i, Value&& value, PairScale&& pair_scale,
                               double grad[3]) {
  sum_over_pairs(
      ctx, list, p, i,
      [&](const NeighborPair& q) {
        return ctx.symmetric_gradient_weight(q.r) * pair_scale(q) * (value(q) + f_i);
      },
      grad);
}
template <class Value>
inline void symmetric_gradient(const SphContext& ctx, const NeighborList& list, const Particles& p,
                               std::size_t i, double f_i, Value&& value, double grad[3]) {
  symmetric_gradient(
      ctx, list, p, i, f_i, value, [](const NeighborPair&) { return 1.0; }, grad);
}

// <div u>_i. value(pair, u_j) writes u_j; u_i is given.
template <class Value>
inline double divergence(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         std::size_t i, const double u_i[3], Value&& value) {
  return with_dimension(ctx.dim, [&](auto dim) {
    double div = 0.0;
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      double u_j[3] = {0, 0, 0};
      value(q, u_j);
      const double f = ctx.gradient_weight(q.r);
      for (int a = 0; a < dim; ++a) div += f * q.d[a] * (u_j[a] - u_i[a]);
    });
    return div;
  });
}

// <lap f>_i, Brookshaw's form of METHOD.md. value(pair) is f_j.
template <class Value>
inline double laplacian(const SphContext& ctx, const NeighborList& list, const Particles& p,
                        std::size_t i, double f_i, Value&& value) {
  double lap = 0.0;
  for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
    lap += ctx.laplacian_weight(q.r, q.r2) * (f_i - value(q));
  });
  return lap;
}

}  // namespace washout
