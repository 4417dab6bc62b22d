#pragma once
// The contact stiffness of one rigid body in its six coordinates (translation, rotation) and a
// bound on the highest squared angular frequency of its contact modes, which sets the contact
// sub-step (contact_substepper.cpp, docs/rigid_bodies.md "Sub-stepping").
//
// A contact at the offset r from the centre of mass pushes along its normal n with k_n and holds
// a tangential spring of k_s in the two directions across it (0 without friction). With
// g(e) = (e, r x e) the change of the contact point's position along e per unit change of the
// body's coordinates, and P(r) = sum over the three axes of g(e) g(e)^T, its stiffness is
//
//   K_i = k_n g(n) g(n)^T + k_s (P(r) - g(n) g(n)^T),   P(r) = [ I  R^T   ],   R = [r]x,
//                                                               [ R  R R^T ]
//
// R R^T = |r|^2 I - r r^T: the part of k_s needs only sum k_s, sum k_s r and sum k_s r r^T.
// B = M^-1 K (M = diag(m, m, m, I)) is similar to the positive semidefinite M^-1/2 K M^-1/2: its
// eigenvalues are the omega^2 of the contact modes. Its trace bounds the largest by the sum of
// all six, and a body resting on a face is about as stiff in several of them. The bound taken
// here is s tr((B / s)^8)^(1/8) with s = tr(B): the eighth root of the sum of the eighth powers
// of the eigenvalues, never below the largest and at most 6^(1/8) = 1.25 times it. Scaled by the
// trace first, the powers stay within [0, 1].
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "engine/contact/dem_contact.hpp"
#include "engine/core/vec3.hpp"

namespace washout::contact {

class ContactStiffness {
 public:
  // A contact of stiffness k (normal, tangential) along the unit normal n, at the offset r from
  // the centre of mass.
  void add(const StepStiffness& k, const Vec3& normal, const Vec3& offset) {
    const Vec3 arm = offset.cross(normal);
    const double g[6] = {normal.x(), normal.y(), normal.z(), arm.x(), arm.y(), arm.z()};
    const double along_normal = k.normal - k.tangential;
    int e = 0;
    for (int i = 0; i < 6; ++i) {
      const double kg = along_normal * g[i];
      for (int j = i; j < 6; ++j) normal_[e++] += kg * g[j];
    }
    if (k.tangential == 0.0) return;
    sum_k_ += k.tangential;
    sum_kr_ += k.tangential * offset;
    const double kx = k.tangential * offset.x(), ky = k.tangential * offset.y();
    sum_krr_[0] += kx * offset.x();
    sum_krr_[1] += kx * offset.y();
    sum_krr_[2] += kx * offset.z();
    sum_krr_[3] += ky * offset.y();
    sum_krr_[4] += ky * offset.z();
    sum_krr_[5] += k.tangential * offset.z() * offset.z();
  }

  // The bound on omega^2 above [1/s^2]; 0 with no contact. inverse_mass = 1/m; the inverse
  // inertia in the world frame (2D: diag(0, 0, 1/I_zz)).
  double largest_frequency2(double inverse_mass, const Eigen::Matrix3d& inertia_inverse) const {
    Eigen::Matrix3d krr;
    krr << sum_krr_[0], sum_krr_[1], sum_krr_[2], sum_krr_[1], sum_krr_[3], sum_krr_[4],
        sum_krr_[2], sum_krr_[4], sum_krr_[5];
    Eigen::Matrix3d kr;  // sum k_s [r]x
    kr << 0.0, -sum_kr_.z(), sum_kr_.y(), sum_kr_.z(), 0.0, -sum_kr_.x(), -sum_kr_.y(), sum_kr_.x(),
        0.0;
    Eigen::Matrix<double, 6, 6> k;
    k.topLeftCorner<3, 3>() = sum_k_ * Eigen::Matrix3d::Identity();
    k.topRightCorner<3, 3>() = kr.transpose();
    k.bottomLeftCorner<3, 3>() = kr;
    k.bottomRightCorner<3, 3>() = krr.trace() * Eigen::Matrix3d::Identity() - krr;
    int e = 0;
    for (int i = 0; i < 6; ++i)
      for (int j = i; j < 6; ++j) {
        k(i, j) += normal_[e];
        if (j != i) k(j, i) += normal_[e];
        ++e;
      }
    Eigen::Matrix<double, 6, 6> b;
    b.topRows<3>() = inverse_mass * k.topRows<3>();
    b.bottomRows<3>() = inertia_inverse * k.bottomRows<3>();
    const double trace = b.trace();
    if (!(trace > 0.0)) return 0.0;
    b /= trace;
    const Eigen::Matrix<double, 6, 6> b2 = b * b;
    const Eigen::Matrix<double, 6, 6> b4 = b2 * b2;
    const double sum_of_eighth_powers = (b4 * b4).trace();
    return std::min(trace, trace * std::pow(std::max(sum_of_eighth_powers, 0.0), 0.125));
  }

 private:
  double normal_[21] = {};  // upper triangle of sum (k_n - k_s) g(n) g(n)^T, row by row
  double sum_k_ = 0.0;      // sum k_s
  Vec3 sum_kr_ = Vec3::Zero();
  double sum_krr_[6] = {};  // sum k_s r r^T: xx, xy, xz, yy, yz, zz
};

}  // namespace washout::contact
