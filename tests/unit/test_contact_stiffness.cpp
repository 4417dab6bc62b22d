// The bound on the contact modes' omega^2 that sets the contact sub-step
// (engine/contact/contact_stiffness.hpp): never below the largest eigenvalue of K v = omega^2 M v
// with K built here from each contact's spring of k in all three directions (Eigen's generalized
// eigensolver), at most 6^(1/8) times it, and well below the trace the sub-steps took before for
// a body resting on a face.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>

#include "engine/contact/contact_stiffness.hpp"

namespace washout::contact {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;

struct Body {
  double mass;
  Eigen::Matrix3d inertia;  // world frame
};

// The largest omega^2 of the contacts, K = sum_i k_n g(n) g(n)^T + k_s (g(t1) g(t1)^T +
// g(t2) g(t2)^T), g(e) = (e, r x e), t1 and t2 across n, against M = diag(m, m, m, I).
struct Contacts {
  Matrix6 k = Matrix6::Zero();
  ContactStiffness stiffness;
  // sum max(k_n, k_s) (1/m + (r x n) . I^-1 (r x n)): the trace the sub-steps took before
  double normal_trace = 0.0;
  void add(const Body& body, double k_n, double k_s, const Vec3& n, const Vec3& r) {
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    for (const auto& [e, k_e] : {std::pair{n, k_n}, std::pair{t1, k_s}, std::pair{t2, k_s}}) {
      Eigen::Matrix<double, 6, 1> g;
      g << e, r.cross(e);
      k += k_e * g * g.transpose();
    }
    stiffness.add({k_n, k_s}, n, r);
    const Vec3 arm = r.cross(n);
    normal_trace += std::max(k_n, k_s) * (1.0 / body.mass + arm.dot(body.inertia.inverse() * arm));
  }
  double exact(const Body& body) const {
    Matrix6 m = Matrix6::Zero();
    m.topLeftCorner<3, 3>() = body.mass * Eigen::Matrix3d::Identity();
    m.bottomRightCorner<3, 3>() = body.inertia;
    Eigen::GeneralizedSelfAdjointEigenSolver<Matrix6> solver(k, m, Eigen::EigenvaluesOnly);
    return solver.eigenvalues().maxCoeff();
  }
  double bound(const Body& body) const {
    return stiffness.largest_frequency2(1.0 / body.mass, body.inertia.inverse());
  }
};

TEST(ContactStiffness, BoundsTheLargestModeWithinAnEighthRootOfSix) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), positive(0.1, 1.0);
  double lowest = 2.0, highest = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    Body body;
    body.mass = 0.1 + 10.0 * positive(random);
    const Eigen::Matrix3d rotation =
        Eigen::Quaterniond(Eigen::Vector4d(unit(random), unit(random), unit(random), 1.0))
            .normalized()
            .toRotationMatrix();
    const Vec3 moments =
        body.mass * 0.01 * Vec3(positive(random), positive(random), positive(random));
    body.inertia = rotation * moments.asDiagonal() * rotation.transpose();
    Contacts contacts;
    const int count = 1 + trial % 40;
    for (int c = 0; c < count; ++c) {
      const Vec3 n = Vec3(unit(random), unit(random), unit(random)).normalized();
      const Vec3 r = 0.2 * Vec3(unit(random), unit(random), unit(random));
      const double k_n = 1e6 * positive(random);
      contacts.add(body, k_n, c % 3 == 0 ? 0.0 : k_n * positive(random), n, r);
    }
    const double exact = contacts.exact(body), bound = contacts.bound(body);
    ASSERT_GE(bound, exact * (1.0 - 1e-9)) << "trial " << trial;
    ASSERT_LE(bound, exact * std::pow(6.0, 0.125) * (1.0 + 1e-9)) << "trial " << trial;
    lowest = std::min(lowest, bound / exact);
    highest = std::max(highest, bound / exact);
  }
  std::printf("bound / largest omega^2 over 300 random bodies: %.4f to %.4f (at most %.4f)\n",
              lowest, highest, std::pow(6.0, 0.125));
}

// Contacts at the centre of mass with k_s = k_n hold the translations only: three modes of
// sum k / m, so the bound is 3^(1/8) of that.
TEST(ContactStiffness, ContactsAtTheCentreHoldTheTranslations) {
  Body body{2.0, Eigen::Vector3d(0.3, 0.2, 0.1).asDiagonal()};
  Contacts contacts;
  contacts.add(body, 5e7, 5e7, Vec3(0, 0.6, 0.8), Vec3::Zero());
  contacts.add(body, 3e7, 3e7, Vec3(1, 0, 0), Vec3::Zero());
  EXPECT_NEAR(contacts.exact(body), 8e7 / 2.0, 1e-6 * 4e7);
  EXPECT_NEAR(contacts.bound(body), std::pow(3.0, 0.125) * 8e7 / 2.0, 1e-9 * 4e7);
}

// scripts/flume.lua's girder (0.24 x 0.48 x 0.06 m, PLA) resting with its whole bottom face on a
// floor at d0 = 5 mm: about as stiff in its six modes (N k / M to 1.5 N k / M), of which the
// normal trace the sub-steps took before adds the normal translation and the two rockings.
// Sub-steps go as the square root of the bound.
TEST(ContactStiffness, AGirderOnItsFaceNeedsFewerSubSteps) {
  const double d0 = 0.005, a = 0.24, b = 0.48, c = 0.06;
  Body body;
  body.mass = 1161.0 * a * b * c;
  body.inertia =
      (body.mass / 12.0 * Vec3(b * b + c * c, a * a + c * c, a * a + b * b)).asDiagonal();
  Contacts contacts;
  for (double x = -0.5 * a + 0.5 * d0; x < 0.5 * a; x += d0)
    for (double y = -0.5 * b + 0.5 * d0; y < 0.5 * b; y += d0)
      contacts.add(body, 1e7, 0.8e7, Vec3::UnitZ(), Vec3(x, y, -0.5 * c));
  const double exact = contacts.exact(body), bound = contacts.bound(body);
  std::printf(
      "girder on its face: normal trace %.4g, bound %.4g, largest omega^2 %.4g 1/s^2; sub-steps "
      "x %.3f\n",
      contacts.normal_trace, bound, exact, std::sqrt(bound / contacts.normal_trace));
  EXPECT_GE(bound, exact * (1.0 - 1e-9));
  // The largest mode, a slide along the face coupled with a rocking, is about 1.5 N k / M; the
  // normal trace 2.9 N k / M.
  EXPECT_LT(bound, 0.6 * contacts.normal_trace);
}

}  // namespace
}  // namespace washout::contact
