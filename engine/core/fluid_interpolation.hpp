#pragma once
// Shepard interpolation of fluid quantities at an arbitrary point (virtual-marker mirror points,
// probes): f(m) = sum_f W(m - x_f) f_f / sum_f W(m - x_f), over fluid particles only.
#include <Eigen/Dense>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/core/dimension.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"

namespace washout {

// Calls accumulate(f, W) for each fluid particle f near m; returns sum_f V W, the kernel-weighted
// fluid volume fraction at m (about 1 inside the fluid, 0 where it is dry).
template <class Accumulate>
double accumulate_fluid_at(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                           const double m[3], Accumulate&& accumulate) {
  const double r2max = 4.0 * ctx.h * ctx.h;
  double weight_sum = 0.0;
  // The arrays' addresses in locals: read through p, they were loaded again after every store
  // the visit makes (any of them might have changed a vector's pointer).
  const double* X = p.position[0].data();
  const double* Y = p.position[1].data();
  const double* Z = p.position[2].data();
  // The fluid within the support found first, without a branch per candidate; the distances
  // taken again for those alone.
  thread_local std::vector<std::uint32_t> found;
  const std::size_t count =
      grid.collect_below(p, m, static_cast<std::uint32_t>(p.fluid_count), r2max, found);
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t f = found[k];
    double d[3] = {m[0] - X[f], m[1] - Y[f], m[2] - Z[f]};
    if (ctx.periodic.any()) ctx.periodic.minimum_image(d);
    const double w = ctx.kernel.value(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    weight_sum += w;
    accumulate(f, w);
  }
  return weight_sum * ctx.volume;
}

// Below this fluid fraction a point is dry: interpolated values there are not trusted.
constexpr double kDryFluidFraction = 0.05;
// Above this fluid fraction a point counts as wet (under water) rather than near the surface.
constexpr double kWetFluidFraction = 0.5;

// The most the linear weights may amplify the fluid's values: sum_f |w_f|, the Lebesgue
// constant of the fit (1 for Shepard weights, 1.0-1.01 at the mirror points of a flat wall). Beyond
// it m lies outside the fluid the fit is made from (a mirror point in a slot narrower than the
// support, or past the few particles at a flow's tip) and the fit extrapolates: at the lifting gate
// of the 3D wash-out it gave markers of 10-33 m/s from fluid moving at 1 m/s (docs/method.md,
// twelfth session).
constexpr double kMaxLinearAmplification = 2.0;

// The fit for a dimension D fixed at compile time (with_dimension): the moments' upper triangle
// is summed in registers, where Eigen's full 4 x 4 outer product of a run-time dimension kept
// sixteen sums in memory (docs/performance.md, thirty-seventh session).
template <int D, class Visit>
double interpolate_fluid_linear_in(const SphContext& ctx, const NeighborGrid& grid,
                                   const Particles& p, const double m[3], Visit&& visit) {
  static_assert(D == 2 || D == 3);
  const double scale = 1.0 / ctx.h;  // keeps A well scaled whatever the units
  // The fluid near m with its weights and scaled offsets, gathered by the search and then
  // summed in a loop of its own, whose sums stay in registers (summed inside the search's visit
  // they lived in memory, each store read back at the next candidate).
  struct Near {
    std::uint32_t f;
    double w;
    double q[D];
  };
  thread_local std::vector<Near> near;
  near.clear();
  const double* position[3] = {p.position[0].data(), p.position[1].data(), p.position[2].data()};
  const double fraction = accumulate_fluid_at(ctx, grid, p, m, [&](std::uint32_t f, double w) {
    Near& entry = near.emplace_back();
    entry.f = f;
    entry.w = w;
    for (int a = 0; a < D; ++a) entry.q[a] = (position[a][f] - m[a]) * scale;
  });
  // The upper triangle of A in named sums: held in arrays, the compiler stored q and the sums
  // to the stack at every particle and read them back (docs/performance.md).
  double s00 = 0, s01 = 0, s02 = 0, s03 = 0, s11 = 0, s12 = 0, s13 = 0, s22 = 0, s23 = 0, s33 = 0;
  for (const Near& entry : near) {
    const double w = entry.w, x = entry.q[0], y = entry.q[1];
    const double wx = w * x, wy = w * y;
    s00 += w;
    s01 += wx;
    s02 += wy;
    s11 += wx * x;
    s12 += wx * y;
    s22 += wy * y;
    if constexpr (D == 3) {
      const double z = entry.q[2], wz = w * z;
      s03 += wz;
      s13 += wx * z;
      s23 += wy * z;
      s33 += wz * z;
    }
  }
  if (fraction < kDryFluidFraction) return fraction;
  // A = sum_f W p_f p_f^T, 4 x 4 whatever D (the unused directions' diagonal 1), so that the
  // condition bound below means the same in 2D and 3D.
  Eigen::Matrix4d A;
  A << s00, s01, s02, s03,  //
      s01, s11, s12, s13,   //
      s02, s12, s22, s23,   //
      s03, s13, s23, (D == 3 ? s33 : 1.0);
  Eigen::Vector4d beta = Eigen::Vector4d::Zero();
  bool linear = false;
  Eigen::LDLT<Eigen::Matrix4d> ldlt(A);
  if (ldlt.info() == Eigen::Success && ldlt.rcond() > 1e-6) {
    beta = ldlt.solve(Eigen::Vector4d(1.0, 0.0, 0.0, 0.0));
    linear = beta.allFinite();
  }
  // The linear weights, computed once: summed for the bound, then handed out.
  thread_local std::vector<double> fitted;
  fitted.clear();
  if (linear) {
    double amplification = 0.0;
    for (const Near& entry : near) {
      double q_dot_beta = beta[0];
      for (int a = 0; a < D; ++a) q_dot_beta += entry.q[a] * beta[a + 1];
      fitted.push_back(entry.w * q_dot_beta);
      amplification += std::abs(fitted.back());
    }
    linear = amplification <= kMaxLinearAmplification;
  }
  const double shepard = 1.0 / s00;
  for (std::size_t k = 0; k < near.size(); ++k)
    visit(near[k].f, linear ? fitted[k] : near[k].w * shepard);
  return fraction;
}

// Linear moving-least-squares interpolation at m over the fluid particles: the weights
// w_f = W(m - x_f) (p_f . beta), p_f = (1, x_f - m), with beta = A^-1 e_1 and
// A = sum_f W p_f p_f^T, reproduce linear fields exactly even where the fluid lies on one side
// of m only (next to a wall), where the plain Shepard average is biased towards the interior.
// Calls visit(f, w_f) (the weights sum to 1); falls back to Shepard weights where the fluid is
// too sparse to fit a gradient or the fit would amplify the values more than
// kMaxLinearAmplification. Returns the fluid fraction at m as accumulate_fluid_at does.
template <class Visit>
double interpolate_fluid_linear(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                                const double m[3], Visit&& visit) {
  return with_dimension(ctx.dim, [&](auto dim) {
    return interpolate_fluid_linear_in<decltype(dim)::value>(ctx, grid, p, m, visit);
  });
}

}  // namespace washout
