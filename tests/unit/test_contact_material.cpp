// Contact constants (METHOD.md Contact): Hertz stiffnesses for the paper's PLA, damping from
// restitution, the friction/restitution table, the Hertz damping inversion, and the single
// contact law (spring, dashpot, Coulomb slider, spring history).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "engine/contact/contact_material.hpp"
#include "engine/contact/dem_contact.hpp"
#include "engine/contact/hertz_damping.hpp"

namespace washout::contact {
namespace {

const Material kPla{"girder", 5.0e9, 0.28, 0.8};

// For one material the formulas reduce to k_n = (4/3) sqrt(r) E / (2 (1 - nu^2)) and
// k_s = 2 sqrt(r) E / ((2 - nu)(1 + nu)); r = d0/2 = 2.5 mm. Values to rounding (1e-14).
TEST(ContactMaterial, HertzStiffnessesForThePaperPla) {
  const double r = 0.0025;
  const double kn = normal_stiffness(r, kPla, kPla), ks = tangential_stiffness(r, kPla, kPla);
  const double kn_expected = 4.0 / 3.0 * std::sqrt(r) * 5e9 / (2 * (1 - 0.28 * 0.28));
  const double ks_expected = 2.0 * std::sqrt(r) * 5e9 / ((2 - 0.28) * (1 + 0.28));
  std::printf("PLA, d0 = 5 mm: k_n = %.4e, k_s = %.4e (k_s/k_n = %.3f)\n", kn, ks, ks / kn);
  EXPECT_NEAR(kn / kn_expected, 1.0, 1e-14);
  EXPECT_NEAR(ks / ks_expected, 1.0, 1e-14);
  EXPECT_NEAR(kn, 1.808449e8, 1e3);
  // Symmetric in the two materials, and a stiffer partner makes a stiffer contact.
  const Material steel{"steel", 2.0e11, 0.3, 0.8};
  EXPECT_DOUBLE_EQ(normal_stiffness(r, kPla, steel), normal_stiffness(r, steel, kPla));
  EXPECT_DOUBLE_EQ(tangential_stiffness(r, kPla, steel), tangential_stiffness(r, steel, kPla));
  EXPECT_GT(normal_stiffness(r, kPla, steel), kn);
}

// c_n of METHOD.md is 2 zeta sqrt(M k) with zeta the damping ratio whose linear restitution is
// eps: the round trip eps -> zeta -> eps is exact to rounding.
TEST(ContactMaterial, DampingFromRestitutionRoundTrips) {
  for (double eps : {0.3, 0.5, 0.8, 0.95}) {
    const double zeta = damping_ratio(eps);
    const double c = normal_damping(eps, 0.2, 1.8e8);
    EXPECT_NEAR(c / (2 * zeta * std::sqrt(0.2 * 1.8e8)), 1.0, 1e-14);
    EXPECT_NEAR(linear_restitution(zeta), eps, 1e-14);
  }
  EXPECT_NEAR(damping_ratio(0.8), 0.0708503, 1e-7);
  EXPECT_EQ(linear_restitution(1.2), 0.0);
}

TEST(ContactMaterial, PairTableIsSymmetricWithDefaults) {
  MaterialTable table;
  const int girder = table.add(kPla);
  const int pier = table.add({"pier", 5.0e9, 0.28, 0.8});
  const int glass = table.add({"glass", 7.0e10, 0.22, 0.5});
  table.set_friction(girder, pier, 0.05);
  table.set_friction(girder, glass, 0.0);
  EXPECT_EQ(table.friction(pier, girder), 0.05);
  EXPECT_EQ(table.friction(glass, girder), 0.0);
  EXPECT_EQ(table.friction(pier, glass), 0.0);  // unset: frictionless
  EXPECT_NEAR(table.restitution(girder, pier), 0.8, 1e-15);
  EXPECT_NEAR(table.restitution(girder, glass), std::sqrt(0.8 * 0.5), 1e-15);
  table.set_restitution(glass, girder, 0.6);
  EXPECT_EQ(table.restitution(girder, glass), 0.6);
  EXPECT_EQ(table.find("pier"), pier);
  EXPECT_EQ(table.find("none"), -1);
  EXPECT_THROW(table.add({"bad", 1e9, 0.6, 0.5}), std::invalid_argument);
  EXPECT_THROW(table.friction(0, 7), std::out_of_range);
}

// The dimensionless Hertz-Tsuji contact xi'' = -xi^{3/2} - alpha xi^{1/4} xi', integrated here
// independently with semi-implicit Euler at a 1e-5 step (first order: ~1e-4 in eps).
double restitution_by_euler(double alpha) {
  double xi = 0.0, rate = 1.0;
  const double step = 1e-5;
  while (true) {
    rate += step * (-xi * std::sqrt(xi) - alpha * std::sqrt(std::sqrt(xi)) * rate);
    xi += step * rate;
    if (xi <= 0.0) return -rate;
  }
}

// The Hertz-Tsuji inversion: no damping gives eps = 1 (tolerance 1e-6: RK4 and the crossing
// interpolation), alpha(eps) reproduces eps (1e-6), and an independent first-order
// integration agrees with it to 5e-4 (its own error is ~1e-4).
TEST(ContactMaterial, HertzDampingInversion) {
  EXPECT_NEAR(hertz_restitution(0.0), 1.0, 1e-6);
  for (double eps : {0.3, 0.5, 0.8, 0.95}) {
    const double alpha = hertz_damping_factor(eps);
    const double check = restitution_by_euler(alpha);
    std::printf(
        "Hertz-Tsuji: eps %.2f needs alpha %.4f (linear 2 zeta = %.4f); independent "
        "integration gives eps %.5f\n",
        eps, alpha, 2 * damping_ratio(eps), check);
    EXPECT_NEAR(hertz_restitution(alpha), eps, 1e-6);
    EXPECT_NEAR(check, eps, 5e-4);
  }
}

PairLaw linear_law(double friction) {
  ContactSettings settings;
  return make_pair_law(settings, 0.0025, kPla, kPla, friction, 0.8);
}

// Normal force: k delta + c d(delta)/dt along n; tangential: spring and dashpot below the
// Coulomb limit (stick), capped at mu F_n above it (slip), with the spring capped too.
TEST(ContactLaw, SpringDashpotAndCoulombSlider) {
  const PairLaw law = linear_law(0.5);
  const double m = 0.2, c = law.damping_factor * std::sqrt(m * law.normal_stiffness);
  ContactKinematics k;
  k.overlap = 1e-7;
  k.overlap_rate = 1e-3;
  k.normal = Vec3::UnitZ();
  k.tangential_velocity = Vec3(1e-4, 0, 0);
  k.damping_mass = m;
  Vec3 spring = Vec3(2e-8, 0, 0);
  const double dt = 1e-6;
  Vec3 f = spring_dashpot_force(law, k, dt, spring);
  const double fn = law.normal_stiffness * 1e-7 + c * 1e-3;
  const double ft = -law.tangential_stiffness * 2e-8 - c * 1e-4;
  EXPECT_NEAR(f.z(), fn, 1e-12 * fn);
  EXPECT_NEAR(f.x(), ft, 1e-12 * std::abs(ft));  // |ft| < mu fn: sticks
  EXPECT_NEAR(spring.x(), 2e-8 + dt * 1e-4, 1e-20);
  // Slip: a large spring; the force is mu F_n against the motion and the spring is capped.
  spring = Vec3(1e-5, 0, 0);
  f = spring_dashpot_force(law, k, dt, spring);
  EXPECT_NEAR(f.x(), -0.5 * fn, 1e-12 * fn);
  EXPECT_NEAR(spring.x(), 0.5 * fn / law.tangential_stiffness + dt * 1e-4, 1e-18);
  // Frictionless: no tangential force at all, no spring.
  spring = Vec3(1e-5, 0, 0);
  f = spring_dashpot_force(linear_law(0.0), k, dt, spring);
  EXPECT_EQ(f.x(), 0.0);
  EXPECT_NEAR(spring.x(), dt * 1e-4, 1e-20);
}

// The spring of a contact whose normal turned is laid back onto the new tangent plane with its
// length kept (a rotating contact does not lose its stored tangential load).
TEST(ContactLaw, TangentialSpringFollowsTheTangentPlane) {
  const PairLaw law = linear_law(10.0);
  ContactKinematics k;
  k.overlap = 1e-6;
  const double angle = 0.1;
  k.normal = Vec3(std::sin(angle), 0, std::cos(angle));
  k.damping_mass = 0.2;
  Vec3 spring(1e-8, 0, 0);
  spring_dashpot_force(law, k, 1e-6, spring);
  EXPECT_NEAR(spring.norm(), 1e-8, 1e-20);
  EXPECT_NEAR(spring.dot(k.normal), 0.0, 1e-22);
}

// The sub-steps skip roots where they cannot change the result (dem_contact.cpp): the spring's
// turn when it already lies in the tangent plane, the slip test's root away from the Coulomb
// limit, the dashpot's root shared by a partner's contacts. Against the law written with every
// root, over contacts on a flat face (spring in the plane), on turned normals, and with
// tangential forces within a few ulps of the limit, the bits are the same.
TEST(ContactLaw, SkippedRootsGiveTheSameBits) {
  const PairLaw law = linear_law(0.3);
  const auto with_every_root = [&](const ContactKinematics& c, double dt, Vec3& spring) {
    const double damping = law.damping_factor * std::sqrt(c.damping_mass * law.normal_stiffness);
    const double normal_force = law.normal_stiffness * c.overlap + damping * c.overlap_rate;
    const double length = spring.norm();
    spring -= spring.dot(c.normal) * c.normal;
    const double projected = spring.norm();
    if (projected > 0.0) spring *= length / projected;
    Vec3 tangential = -law.tangential_stiffness * spring - damping * c.tangential_velocity;
    const double limit = law.friction * std::max(normal_force, 0.0);
    const double magnitude = tangential.norm();
    if (magnitude > limit) {
      tangential = magnitude > 0.0 ? Vec3(tangential * (limit / magnitude)) : Vec3::Zero();
      spring = -tangential / law.tangential_stiffness;
    }
    spring += dt * c.tangential_velocity;
    return Vec3(normal_force * c.normal + tangential);
  };
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int slips = 0, sticks = 0, near_limit = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    ContactKinematics k;
    k.overlap = 1e-7 * (1.5 + 0.5 * unit(random));
    k.overlap_rate = 1e-3 * unit(random);
    k.normal = trial % 2 ? Vec3::UnitZ() : Vec3(unit(random), unit(random), 1.0).normalized();
    k.tangential_velocity = 1e-3 * Vec3(unit(random), unit(random), unit(random));
    k.tangential_velocity -= k.tangential_velocity.dot(k.normal) * k.normal;
    k.damping_mass = 0.5;
    Vec3 spring = 1e-7 * Vec3(unit(random), unit(random), 0.0);  // in the plane of a flat face
    const double dt = 1e-6;
    // Every fourth trial puts the tangential force at the limit, give or take a few ulps.
    if (trial % 4 == 1) {  // a flat face's contact
      const double dashpot = law.damping_factor * std::sqrt(k.damping_mass * law.normal_stiffness);
      const double limit =
          law.friction * std::max(law.normal_stiffness * k.overlap + dashpot * k.overlap_rate, 0.0);
      k.tangential_velocity.setZero();
      if (limit > 0.0) {
        spring = Vec3(limit / law.tangential_stiffness * (1.0 + 4e-16 * unit(random)), 0.0, 0.0);
        ++near_limit;
      }
    }
    Vec3 spring_reference = spring;
    const Vec3 f =
        spring_dashpot_force(law, k, dashpot_coefficient(law, k.damping_mass), dt, spring);
    const Vec3 f_reference = with_every_root(k, dt, spring_reference);
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(f[a], f_reference[a]) << "trial " << trial;
      ASSERT_EQ(spring[a], spring_reference[a]) << "trial " << trial;
    }
    const double limit = law.friction * std::max(f.dot(k.normal), 0.0);
    (Vec3(f - f.dot(k.normal) * k.normal).norm() >= limit * (1.0 - 1e-12) ? slips : sticks) += 1;
  }
  std::printf(
      "20000 contacts, %d slipping, %d sticking, %d within ulps of the Coulomb limit: force and "
      "spring to the bit\n",
      slips, sticks, near_limit);
  EXPECT_GT(near_limit, 4000);
  EXPECT_GT(slips, 1000);
  EXPECT_GT(sticks, 1000);
}

// Without tension the normal force never pulls; with it (default) it may at the end of a
// contact, as the analytic linear spring-dashpot does.
TEST(ContactLaw, TensionOption) {
  ContactSettings settings;
  ContactKinematics k;
  k.overlap = 1e-9;
  k.overlap_rate = -1.0;  // separating fast
  k.normal = Vec3::UnitZ();
  k.damping_mass = 0.2;
  Vec3 spring = Vec3::Zero();
  const PairLaw with = make_pair_law(settings, 0.0025, kPla, kPla, 0.0, 0.8);
  EXPECT_LT(spring_dashpot_force(with, k, 1e-6, spring).z(), 0.0);
  settings.allow_tension = false;
  const PairLaw without = make_pair_law(settings, 0.0025, kPla, kPla, 0.0, 0.8);
  EXPECT_EQ(spring_dashpot_force(without, k, 1e-6, spring).z(), 0.0);
}

}  // namespace
}  // namespace washout::contact
