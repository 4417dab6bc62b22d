// Body model: mass, centre of mass, inertia from the particles against the exact box, cylinder
// and disc formulas, principal axes, surface lists.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/rigid/body_model.hpp"
#include "engine/rigid/lattice_body.hpp"

namespace washout::rigid {
namespace {

double relative(double measured, double exact) { return std::abs(measured - exact) / exact; }

// A box filled on a cell-centred lattice: the point masses give sum x^2 = n (a^2 - d0^2)/12 per
// axis, the cell term adds n d0^2/12 back per axis, so I = M (b^2 + c^2)/12 exactly: only
// rounding error (tolerance 1e-12) is left.
TEST(RigidBodyModel, BoxInertiaIsExactWithCellInertia) {
  const double a = 0.3, b = 0.2, c = 0.1, d0 = 0.01, rho = 1161.0;
  BodyModel m = make_body_model(lattice_box(3, d0, Vec3(1, 2, 3), Vec3(1 + a, 2 + b, 3 + c), rho));
  const double mass = rho * a * b * c;
  const Vec3 exact(mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12,
                   mass * (a * a + b * b) / 12);
  double worst = 0.0;
  for (int k = 0; k < 3; ++k) worst = std::max(worst, relative(m.inertia(k, k), exact[k]));
  const double off_diagonal =
      (m.inertia - Eigen::Matrix3d(m.inertia.diagonal().asDiagonal())).cwiseAbs().maxCoeff() /
      exact.maxCoeff();
  std::printf("box 0.3x0.2x0.1, d0 0.01: mass error %.2e, inertia error %.2e, off-diag %.2e\n",
              relative(m.mass, mass), worst, off_diagonal);
  EXPECT_LT(relative(m.mass, mass), 1e-12);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(off_diagonal, 1e-12);
  EXPECT_LT((m.centre_of_mass - Vec3(1.15, 2.1, 3.05)).norm(), 1e-12);
}

// Point masses alone miss exactly M d0^2/6 per axis (the formula of the lattice sum above).
TEST(RigidBodyModel, PointMassInertiaMissesTheCellTerm) {
  const double a = 0.3, b = 0.2, c = 0.1, d0 = 0.01, rho = 1000.0;
  BodyParticles p = lattice_box(3, d0, Vec3::Zero(), Vec3(a, b, c), rho);
  p.particle_inertia = ParticleInertia::kPointMass;
  BodyModel m = make_body_model(p);
  const double mass = rho * a * b * c;
  const double exact = mass * (b * b + c * c) / 12;
  const double lattice = mass * (b * b + c * c - 2 * d0 * d0) / 12;
  std::printf("point masses: I_x error against the box %.3e (predicted %.3e)\n",
              relative(m.inertia(0, 0), exact), relative(lattice, exact));
  EXPECT_LT(relative(m.inertia(0, 0), lattice), 1e-12);
}

TEST(RigidBodyModel, RectangleInertia2D) {
  const double a = 0.3, b = 0.03, d0 = 0.005, rho = 1161.0;
  BodyModel m = make_body_model(lattice_box(2, d0, Vec3::Zero(), Vec3(a, b, 0), rho));
  const double mass = rho * a * b;  // per metre of thickness
  const double exact = mass * (a * a + b * b) / 12;
  std::printf("2D rectangle: I_zz error %.2e\n", relative(m.inertia(2, 2), exact));
  EXPECT_LT(relative(m.mass, mass), 1e-12);
  EXPECT_LT(relative(m.inertia(2, 2), exact), 1e-12);
  EXPECT_EQ(m.centre_of_mass.z(), 0.0);
  EXPECT_NEAR(m.inertia_inverse(2, 2) * m.inertia(2, 2), 1.0, 1e-14);
}

// A lattice cylinder has a staircase side: its outer particles lie anywhere within about d0/2
// of the true radius, so I ~ M R^2 is off by up to ~d0/R. Compared with M R^2/2 and
// M (3R^2 + L^2)/12 for the lattice's own mass M, tolerance 0.5 d0/R (6 % at R = 8 d0, 3 % at
// R = 16 d0), and the error must fall with d0.
TEST(RigidBodyModel, CylinderInertiaConvergesToTheExactFormula) {
  const double radius = 0.04, length = 0.1, rho = 1000.0;
  double previous = 1.0;
  for (int cells : {8, 16}) {
    const double d0 = radius / cells;
    BodyModel m = make_body_model(lattice_cylinder(d0, Vec3::Zero(), radius, length, rho));
    const double axial = m.mass * radius * radius / 2;
    const double transverse = m.mass * (3 * radius * radius + length * length) / 12;
    const double e_axial = relative(m.inertia(2, 2), axial);
    const double e_transverse = relative(m.inertia(0, 0), transverse);
    const double e_mass = relative(m.mass, rho * std::numbers::pi * radius * radius * length);
    std::printf("cylinder R/d0 = %2d: mass %.2e, I_axis %.2e, I_transverse %.2e\n", cells, e_mass,
                e_axial, e_transverse);
    const double tolerance = 0.5 / cells;
    EXPECT_LT(e_axial, tolerance);
    EXPECT_LT(e_transverse, tolerance);
    EXPECT_LT(e_axial, previous);
    previous = e_axial;
  }
}

TEST(RigidBodyModel, DiscInertia2D) {
  const double radius = 0.05, d0 = radius / 20, rho = 1000.0;
  BodyModel m = make_body_model(lattice_ball(2, d0, Vec3(0.3, 0.4, 0), radius, rho));
  const double exact = m.mass * radius * radius / 2;
  std::printf("disc R/d0 = 20: I_zz error %.2e\n", relative(m.inertia(2, 2), exact));
  EXPECT_LT(relative(m.inertia(2, 2), exact), 0.01);
  EXPECT_LT((m.centre_of_mass - Vec3(0.3, 0.4, 0)).norm(), 1e-12);
  EXPECT_GT(m.surface_index.size(), 0u);
  EXPECT_EQ(m.contact_index.size(), m.surface_index.size());
}

// An L-shaped body (two boxes): centre of mass by moments, and principal axes that form a
// proper rotation diagonalising the (non-diagonal) inertia tensor.
TEST(RigidBodyModel, CentreOfMassAndPrincipalAxesOfAnLShape) {
  const double d0 = 0.01;
  BodyParticles p = lattice_box(3, d0, Vec3(0, 0, 0), Vec3(0.2, 0.04, 0.04), 1000.0);
  BodyParticles q = lattice_box(3, d0, Vec3(0, 0.04, 0), Vec3(0.04, 0.2, 0.04), 1000.0);
  for (std::size_t i = 0; i < q.position.size(); ++i) p.position.push_back(q.position[i]);
  p.surface.clear();
  BodyModel m = make_body_model(p);
  const double m1 = 0.2 * 0.04 * 0.04, m2 = 0.04 * 0.16 * 0.04;
  const Vec3 exact = (m1 * Vec3(0.1, 0.02, 0.02) + m2 * Vec3(0.02, 0.12, 0.02)) / (m1 + m2);
  const Eigen::Matrix3d a = m.principal_axes;
  const Eigen::Matrix3d back = a * m.principal_moments.asDiagonal() * a.transpose();
  std::printf("L shape: centre of mass error %.2e m, I_xy/I_xx = %.3f, principal error %.2e\n",
              (m.centre_of_mass - exact).norm(), m.inertia(0, 1) / m.inertia(0, 0),
              (back - m.inertia).norm() / m.inertia.norm());
  EXPECT_LT((m.centre_of_mass - exact).norm(), 1e-12);
  EXPECT_GT(std::abs(m.inertia(0, 1)), 0.1 * m.inertia(0, 0));  // really not diagonal
  EXPECT_NEAR(a.determinant(), 1.0, 1e-12);
  EXPECT_LT((back - m.inertia).norm() / m.inertia.norm(), 1e-12);
  EXPECT_EQ(m.contact_index.size(), m.particle_count());  // no surface: every particle touches
}

TEST(RigidBodyModel, SurfaceListsFollowTheMask) {
  BodyModel m = make_body_model(lattice_box(3, 0.01, Vec3::Zero(), Vec3(0.05, 0.04, 0.03), 1.0));
  const std::size_t interior = 3 * 2 * 1;
  EXPECT_EQ(m.particle_count(), 60u);
  EXPECT_EQ(m.surface_index.size(), 60u - interior);
  EXPECT_EQ(m.contact_offset.size(), m.surface_index.size());
  for (std::size_t s = 0; s < m.surface_index.size(); ++s)
    EXPECT_NEAR(m.surface_normal[s].norm(), 1.0, 1e-14);
}

TEST(RigidBodyModel, RejectsBadInput) {
  BodyParticles p;
  EXPECT_THROW(make_body_model(p), std::invalid_argument);
  p = lattice_box(3, 0.01, Vec3::Zero(), Vec3(0.02, 0.02, 0.02), 1.0);
  p.area.pop_back();
  EXPECT_THROW(make_body_model(p), std::invalid_argument);
}

}  // namespace
}  // namespace washout::rigid
