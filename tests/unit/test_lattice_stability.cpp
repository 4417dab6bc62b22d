// Linear stability of a particle lattice under the symmetric pressure gradient (corrector.cpp),
// the analysis behind docs/method.md "The fifteenth session". With a uniform pressure P the
// symmetric form pushes particle i by -(1/rho0) sum_j V c (P_i + P_j) grad W_ij (c the lattice
// normalisation). Displace the lattice by a wave u_j = U exp(i k . x_j): to first order
//   d^2 U / dt^2 = -(2 P / rho0) M(k) U,   M(k) = sum_j V c H(x_j) (1 - cos(k . x_j)),
// H the Hessian of W. A negative eigenvalue of M(k) is a mode that grows at
// sqrt(2 P |lambda| / rho0) whatever the time step, and the projection cannot stop it where it
// keeps the density (k with no component along the polarisation: whole columns sliding).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/core/sph_context.hpp"

namespace washout {
namespace {

struct SoftestMode {
  double eigenvalue = 0.0;  // [1/m^2]: lowest eigenvalue of M(k) over the sampled zone
  Eigen::Vector3d wave;     // k d0 / pi of that mode
  Eigen::Vector3d polarisation;
  double largest = 0.0;  // the largest eigenvalue met, for scale
};

// H(x) = W'' e e^T + (W'/r) (I - e e^T) from dW/dr, W'' by a central difference.
template <class FirstDerivative>
Eigen::Matrix3d hessian(FirstDerivative&& first, const Eigen::Vector3d& x, double dr) {
  const double r = x.norm();
  const double second = (first(r + dr) - first(r - dr)) / (2.0 * dr);
  const Eigen::Vector3d e = x / r;
  return second * e * e.transpose() +
         first(r) / r * (Eigen::Matrix3d::Identity() - e * e.transpose());
}

Eigen::Matrix3d kernel_hessian(const CubicSplineKernel& W, const Eigen::Vector3d& x) {
  return hessian([&](double r) { return W.derivative(r); }, x, 1e-6 * W.h());
}

// V c H of the symmetric gradient's pair force: the cubic spline's, or the Wendland shape's
// where the context uses it (symmetric_kernel = "wendland", or "auto" in 3D).
Eigen::Matrix3d pair_force_hessian(const SphContext& ctx, const Eigen::Vector3d& x) {
  if (!ctx.symmetric_has_own_kernel())
    return ctx.volume * ctx.gradient_correction * kernel_hessian(ctx.kernel, x);
  const auto first = [&](double r) { return r * ctx.symmetric_shape.derivative_over_r(r); };
  return ctx.volume * ctx.symmetric_correction * hessian(first, x, 1e-6 * ctx.d0);
}

// The lattice sites within the support 2h of the origin, the origin excluded.
std::vector<Eigen::Vector3d> lattice_sites(const SphContext& ctx) {
  const int reach = static_cast<int>(std::ceil(2.0 * ctx.h / ctx.d0));
  std::vector<Eigen::Vector3d> sites;
  for (int c = (ctx.dim == 3 ? -reach : 0); c <= (ctx.dim == 3 ? reach : 0); ++c)
    for (int b = -reach; b <= reach; ++b)
      for (int a = -reach; a <= reach; ++a) {
        const Eigen::Vector3d x = ctx.d0 * Eigen::Vector3d(a, b, c);
        if ((a != 0 || b != 0 || c != 0) && x.norm() < 2.0 * ctx.h) sites.push_back(x);
      }
  return sites;
}

// U^T M(k) U for one wave k [1/m] and unit polarisation U.
double stiffness(const SphContext& ctx, const Eigen::Vector3d& k, const Eigen::Vector3d& U) {
  double sum = 0.0;
  for (const Eigen::Vector3d& x : lattice_sites(ctx))
    sum += U.dot(pair_force_hessian(ctx, x) * U) * (1.0 - std::cos(k.dot(x)));
  return sum;
}

// The softest mode of M(k) on the k grid (0..pi/d0 in samples steps along each axis).
SoftestMode softest_mode(const SphContext& ctx, int samples) {
  const std::vector<Eigen::Vector3d> sites = lattice_sites(ctx);
  std::vector<Eigen::Matrix3d> hessians;
  for (const Eigen::Vector3d& x : sites) hessians.push_back(pair_force_hessian(ctx, x));
  SoftestMode softest;
  softest.eigenvalue = std::numeric_limits<double>::max();
  const int kz_samples = ctx.dim == 3 ? samples : 0;
  for (int a = 0; a <= samples; ++a)
    for (int b = 0; b <= samples; ++b)
      for (int c = 0; c <= kz_samples; ++c) {
        if (a == 0 && b == 0 && c == 0) continue;
        const Eigen::Vector3d k =
            std::numbers::pi / ctx.d0 * Eigen::Vector3d(a, b, c) / double(samples);
        Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
        for (std::size_t s = 0; s < sites.size(); ++s)
          M += hessians[s] * (1.0 - std::cos(k.dot(sites[s])));
        const int d = ctx.dim;
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M.topLeftCorner(d, d));
        softest.largest = std::max(softest.largest, eig.eigenvalues()(d - 1));
        if (eig.eigenvalues()(0) < softest.eigenvalue) {
          softest.eigenvalue = eig.eigenvalues()(0);
          softest.wave = k * ctx.d0 / std::numbers::pi;
          softest.polarisation = Eigen::Vector3d::Zero();
          softest.polarisation.head(d) = eig.eigenvectors().col(0).cwiseAbs();
        }
      }
  return softest;
}

// The Hessian is the derivative of the kernel gradient the operators use.
TEST(LatticeStability, HessianIsTheDerivativeOfTheGradient) {
  const CubicSplineKernel W(3, 0.012);
  const auto gradient = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(W.derivative_over_r(x.norm()) * x);
  };
  double worst = 0.0;
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(0.01, 0.01, 0),
                                   Eigen::Vector3d(0.004, -0.007, 0.012)}) {
    const Eigen::Matrix3d H = kernel_hessian(W, x);
    for (int b = 0; b < 3; ++b) {
      const Eigen::Vector3d step = 1e-7 * Eigen::Vector3d::Unit(b);
      const Eigen::Vector3d column = (gradient(x + step) - gradient(x - step)) / 2e-7;
      worst = std::max(worst, (column - H.col(b)).norm() / H.norm());
    }
  }
  std::printf("largest relative difference from a finite difference of grad W: %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);  // the central differences' truncation and round-off
}

// 2D at METHOD.md's h = 1.2 d0: no mode grows, which is why 2D still water stays still
// (docs/method.md: H/20 for 10 s, largest speed 1.5e-2 m/s).
TEST(LatticeStability, SquareLatticeIsNeutralAtTheDefaultSmoothingLength) {
  const SphContext ctx(2, 0.01, 1.2, 1000.0, PeriodicBox{});
  const SoftestMode m = softest_mode(ctx, 32);
  std::printf(
      "2D, h = 1.2 d0: lowest eigenvalue %.3e 1/m^2 (largest %.3e) at k d0/pi = (%.2f, %.2f)\n",
      m.eigenvalue, m.largest, m.wave[0], m.wave[1]);
  EXPECT_GT(m.eigenvalue, -1e-9 * m.largest);  // zero up to round-off: neutral, not unstable
}

// 3D at h = 1.2 d0: modes grow. The softest (k d0/pi = (1/2, 1, 1) polarised along x)
// compresses the columns, which the projection opposes; the softest that keeps the density,
// whole columns sliding along their axis in a checkerboard (k = (0, pi, pi) / d0), is the mode
// the eighth session saw in the still tank. At the floor of the 0.1 m tank
// (scenes/hydrostatic_3d.lua, P = rho0 g H) the two bracket the measured e-folding time of
// about 0.04 s.
TEST(LatticeStability, CubicLatticeBucklesInColumnsUnderPressure) {
  const SphContext ctx(3, 0.01, 1.2, 1000.0, PeriodicBox{});
  const SoftestMode m = softest_mode(ctx, 16);
  const double pi = std::numbers::pi;
  const double columns =
      stiffness(ctx, Eigen::Vector3d(0, pi / ctx.d0, pi / ctx.d0), Eigen::Vector3d::UnitX());
  const double floor_pressure = 1000.0 * 9.81 * 0.1;
  const auto e_folding = [&](double eigenvalue) {
    return 1.0 / std::sqrt(2.0 * floor_pressure * std::max(1e-300, -eigenvalue) / ctx.rho0);
  };
  std::printf(
      "3D, h = 1.2 d0: lowest eigenvalue %.3e 1/m^2 (largest %.3e) at k d0/pi = "
      "(%.2f, %.2f, %.2f), polarisation (%.2f, %.2f, %.2f): e-folding %.3f s at the "
      "floor of a 0.1 m tank\n",
      m.eigenvalue, m.largest, m.wave[0], m.wave[1], m.wave[2], m.polarisation[0],
      m.polarisation[1], m.polarisation[2], e_folding(m.eigenvalue));
  std::printf(
      "columns sliding in a checkerboard: %.3e 1/m^2, e-folding %.3f s (measured in the "
      "tank: about 0.04 s)\n",
      columns, e_folding(columns));
  EXPECT_LT(m.eigenvalue, -0.05 * m.largest);  // clearly unstable, not a round-off
  ASSERT_LT(columns, 0.0);
  EXPECT_LT(e_folding(m.eigenvalue), 0.04);
  EXPECT_GT(e_folding(columns), 0.04);
}

// symmetric_kernel = "wendland": the pair force of a Wendland C2 shape of support 2 d0 leaves
// no mode growing, in 2D or 3D (its lowest eigenvalue is positive, at the zone's centre).
TEST(LatticeStability, WendlandPairForceKeepsTheLatticeStableIn2dAnd3d) {
  for (int dim : {2, 3}) {
    SphContext ctx(dim, 0.01, 1.2, 1000.0, PeriodicBox{});
    ctx.use_wendland_symmetric_gradient();
    const SoftestMode m = softest_mode(ctx, dim == 2 ? 32 : 16);
    std::printf(
        "%dD, Wendland C2 of support 2 d0: lowest eigenvalue %.3e 1/m^2 (largest %.3e) "
        "at k d0/pi = (%.2f, %.2f, %.2f)\n",
        dim, m.eigenvalue, m.largest, m.wave[0], m.wave[1], m.wave[2]);
    EXPECT_GT(m.eigenvalue, -1e-9 * m.largest);
    const double pi = std::numbers::pi;
    const Eigen::Vector3d columns = dim == 3 ? Eigen::Vector3d(0, pi / ctx.d0, pi / ctx.d0)
                                             : Eigen::Vector3d(0, pi / ctx.d0, 0);
    EXPECT_GT(stiffness(ctx, columns, Eigen::Vector3d::UnitX()), 0.0);
  }
}

}  // namespace
}  // namespace washout
