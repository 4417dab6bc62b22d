// Signed distances and normals of the wall shapes: exact values at chosen points, unit normals
// equal to the gradient (checked by central differences away from edges).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "engine/contact/wall.hpp"

namespace washout::contact {
namespace {

// The normal is the gradient of the distance: central differences of width 1e-6 agree to 1e-6.
void expect_normal_is_gradient(const WallShape& shape, const Vec3& x) {
  Vec3 n;
  signed_distance(shape, x, &n);
  Vec3 gradient;
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = h * Vec3::Unit(k);
    gradient[k] = (signed_distance(shape, x + e) - signed_distance(shape, x - e)) / (2 * h);
  }
  EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  EXPECT_LT((n - gradient).norm(), 1e-6) << "at " << x.transpose();
}

TEST(ContactWall, TiltedPlane) {
  const double angle = 0.3;
  const PlaneWall plane{Vec3(0, 0, 1), Vec3(-std::sin(angle), 0, std::cos(angle))};
  Vec3 n;
  EXPECT_NEAR(signed_distance(plane, Vec3(0, 0, 1.5), &n), 0.5 * std::cos(angle), 1e-15);
  EXPECT_LT((n - plane.normal).norm(), 1e-15);
  EXPECT_NEAR(signed_distance(plane, Vec3(1, 0, 1)), -std::sin(angle), 1e-15);
}

TEST(ContactWall, BoxObstacleFacesEdgesCornersAndInside) {
  BoxObstacle box;
  box.centre = Vec3(1, 2, 3);
  box.half_size = Vec3(0.5, 0.2, 0.1);
  Vec3 n;
  EXPECT_NEAR(signed_distance(box, Vec3(1, 2, 3.3), &n), 0.2, 1e-15);  // above the top face
  EXPECT_LT((n - Vec3::UnitZ()).norm(), 1e-15);
  EXPECT_NEAR(signed_distance(box, Vec3(1.8, 2.6, 3), &n), 0.5, 1e-15);  // off an edge: 0.3, 0.4
  EXPECT_LT((n - Vec3(0.6, 0.8, 0)).norm(), 1e-15);
  EXPECT_NEAR(signed_distance(box, Vec3(1, 2, 2.95), &n), -0.05, 1e-15);  // inside, near bottom
  EXPECT_LT((n + Vec3::UnitZ()).norm(), 1e-15);
  for (const Vec3& x :
       {Vec3(1.1, 2.05, 3.4), Vec3(1.9, 2.5, 3.3), Vec3(0.2, 1.0, 2.0), Vec3(1.2, 2.0, 3.05)})
    expect_normal_is_gradient(box, x);
  // Rotated by 90 degrees about z: x and y extents swap.
  box.rotation = Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()).toRotationMatrix();
  EXPECT_NEAR(signed_distance(box, Vec3(1, 2.9, 3)), 0.4, 1e-12);
  // 2D: unbounded in z.
  box.rotation.setIdentity();
  box.half_size.z() = 0.0;
  EXPECT_NEAR(signed_distance(box, Vec3(1.0, 2.3, 100.0), &n), 0.1, 1e-15);
}

// Beyond one face the box takes that face's distance and normal without the root of the general
// formula (wall.cpp); the shortcut must give the general formula's bits, since the contact
// sub-steps run it hundreds of times a step and a last-bit change would move a tumbling girder.
TEST(ContactWall, BoxObstacleBeyondOneFaceGivesTheGeneralFormulasBits) {
  BoxObstacle box;
  box.centre = Vec3(0.3, -0.1, 0.03);
  box.half_size = Vec3(0.06, 0.06, 0.03);
  box.rotation = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const auto general = [&](const Vec3& x, Vec3& n) {  // the distance to a face, edge or corner
    const Vec3 p = box.rotation.transpose() * (x - box.centre);
    const Vec3 q = p.cwiseAbs() - box.half_size;
    const Vec3 outside = q.cwiseMax(0.0);
    const double d = outside.norm();
    Vec3 local;
    for (int k = 0; k < 3; ++k) local[k] = (p[k] < 0.0 ? -1.0 : 1.0) * outside[k] / d;
    n = box.rotation * local;
    return d;
  };
  std::mt19937 random(11);
  std::uniform_real_distribution<double> around(-0.1, 0.1);
  int faces = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 x = box.centre + Vec3(around(random), around(random), around(random));
    const Vec3 q = (box.rotation.transpose() * (x - box.centre)).cwiseAbs() - box.half_size;
    if ((q.array() > 0.0).count() != 1) continue;
    ++faces;
    Vec3 n, n_general;
    const double d = box.distance(x, n), d_general = general(x, n_general);
    ASSERT_EQ(d, d_general) << "at " << x.transpose();
    for (int k = 0; k < 3; ++k) ASSERT_EQ(n[k], n_general[k]) << "at " << x.transpose();
  }
  EXPECT_GT(faces, 5000);
}

TEST(ContactWall, CylinderObstacle) {
  CylinderObstacle c{Vec3::Zero(), Vec3::UnitY(), 0.5, 1.0};
  Vec3 n;
  EXPECT_NEAR(signed_distance(c, Vec3(0.8, 0.3, 0), &n), 0.3, 1e-15);
  EXPECT_LT((n - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_NEAR(signed_distance(c, Vec3(0, 1.2, 0.1), &n), 0.2, 1e-15);  // beyond the cap
  EXPECT_NEAR(signed_distance(c, Vec3(0.0, 0.0, 0.1)), -0.4, 1e-15);
  for (const Vec3& x : {Vec3(0.7, 0.2, 0.3), Vec3(0.7, 1.3, 0.1), Vec3(0.1, 0.2, 0.15)})
    expect_normal_is_gradient(c, x);
  c.half_length = 0.0;  // infinite
  EXPECT_NEAR(signed_distance(c, Vec3(0, 100, 0.7)), 0.2, 1e-12);
}

TEST(ContactWall, CustomSignedDistance) {
  const SignedDistanceWall sphere{[](const Vec3& x, Vec3* n) {
    *n = x.normalized();
    return x.norm() - 1.0;
  }};
  Vec3 n;
  EXPECT_NEAR(signed_distance(sphere, Vec3(0, 3, 0), &n), 2.0, 1e-15);
  EXPECT_LT((n - Vec3::UnitY()).norm(), 1e-15);
}

// A flume as a union of five slabs (floor, two side walls, two end walls), 1 m x 0.4 m. Around
// points near its floor-side corner and along its side walls, the distance over the parts the
// mask keeps is the distance over all of them, value and normal to the bit, for every point
// within the margin, and the mask drops the parts that cannot be nearest there.
TEST(ContactWall, UnionWallMaskKeepsTheNearestPart) {
  const auto slab = [](Vec3 lower, Vec3 upper) {
    BoxObstacle box;
    box.centre = 0.5 * (lower + upper);
    box.half_size = 0.5 * (upper - lower);
    return PrimitiveWall(box);
  };
  const double t = 0.02;  // slab thickness
  const UnionWall flume{std::make_shared<const std::vector<PrimitiveWall>>(
      std::vector{slab(Vec3(-t, -t, -t), Vec3(1 + t, 0.4 + t, 0)),      // floor
                  slab(Vec3(-t, -t, -t), Vec3(1 + t, 0, 0.5)),          // side y = 0
                  slab(Vec3(-t, 0.4, -t), Vec3(1 + t, 0.4 + t, 0.5)),   // side y = 0.4
                  slab(Vec3(-t, -t, -t), Vec3(0, 0.4 + t, 0.5)),        // end x = 0
                  slab(Vec3(1, -t, -t), Vec3(1 + t, 0.4 + t, 0.5))})};  // end x = 1
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double margin = 0.01;
  int compared = 0;
  for (const Vec3& centre : {Vec3(0.5, 0.012, 0.015), Vec3(0.5, 0.2, 0.011), Vec3(0.3, 0.39, 0.2),
                             Vec3(0.005, 0.005, 0.005)}) {
    const UnionWall::Mask mask = flume.parts_within(centre, margin);
    EXPECT_NE(mask & 0x1fu, 0x1fu) << "no part dropped at " << centre.transpose();
    for (int k = 0; k < 200; ++k) {
      Vec3 offset(unit(random), unit(random), unit(random));
      offset *= 0.999 * margin / std::max(1.0, offset.norm());
      const Vec3 x = centre + offset;
      Vec3 n_all, n_masked;
      const double all = flume.distance(x, n_all);
      const double masked = flume.distance(x, n_masked, mask);
      EXPECT_EQ(all, masked) << "at " << x.transpose();
      EXPECT_EQ(n_all, n_masked) << "at " << x.transpose();
      ++compared;
    }
  }
  // The side wall beside a point 12 mm from it and 15 mm above the floor: floor and that side
  // only (the far side and the ends are more than twice the margin farther).
  EXPECT_EQ(flume.parts_within(Vec3(0.5, 0.012, 0.015), margin), 0x3u);
  EXPECT_EQ(compared, 800);
}

}  // namespace
}  // namespace washout::contact
