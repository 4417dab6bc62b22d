#pragma once
// Fixed boundaries for contact, described by their signed distance function (positive outside
// the solid, where bodies are; its gradient is the unit normal pointing out of the solid).
// A smooth function instead of wall particles: a body slides on a flat wall without lattice
// bumps. Penetration of a body particle of radius r at x: delta = r - sdf(x), normal grad sdf.
// Shapes are plain structs; the per-particle loop is compiled once per shape type (std::visit
// outside the loop), so there is no virtual call per particle except for SignedDistanceWall
// (a UnionWall visits its parts' variant).
#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "engine/core/vec3.hpp"

namespace washout::contact {

// A half-space: the solid lies on the side opposite to `normal` (a floor has normal +z).
struct PlaneWall {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, out of the solid
  double distance(const Vec3& x, Vec3& n) const {
    n = normal;
    return normal.dot(x - point);
  }
};

// A solid box (a pier, an obstacle). half_size.z() <= 0 makes it unbounded along its local z
// (a rectangle in 2D).
struct BoxObstacle {
  Vec3 centre = Vec3::Zero();
  Vec3 half_size = Vec3::Ones();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // box frame -> world
  double distance(const Vec3& x, Vec3& n) const;
};

// A solid cylinder. half_length <= 0 makes it infinite (a disc in 2D with axis z).
struct CylinderObstacle {
  Vec3 centre = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();  // unit
  double radius = 1.0;
  double half_length = 0.0;
  double distance(const Vec3& x, Vec3& n) const;
};

// A sphere (3D only: a 2D sphere is a disc, an infinite cylinder along z).
struct SphereObstacle {
  Vec3 centre = Vec3::Zero();
  double radius = 1.0;
  double distance(const Vec3& x, Vec3& n) const {
    const Vec3 d = x - centre;
    const double r = d.norm();
    n = r > 0.0 ? Vec3(d / r) : Vec3::UnitZ();
    return r - radius;
  }
};

using PrimitiveWall = std::variant<BoxObstacle, CylinderObstacle, SphereObstacle>;

// A union of primitive solids (a flume's floor, side and end walls): sdf = the minimum over the
// parts, the normal that of the nearest (the first of equals), so that a particle over the seam
// of two touching parts feels one contact, not two. Each part's distance is exact, so it changes
// by no more than the point moves: a part farther than the nearest by more than twice a margin
// cannot be the nearest anywhere within that margin of the point. `parts_within` lists the
// others as a mask, and `distance` over a mask gives the same value and normal as over all
// parts for any point within the margin (contact_forces.cpp keeps such a mask per particle of a
// near list: a girder's end beside one side wall tries that wall, not the five parts).
struct UnionWall {
  using Mask = std::uint32_t;
  static constexpr Mask kAll = ~Mask(0);  // also what a union of more than 32 parts uses
  std::shared_ptr<const std::vector<PrimitiveWall>> parts;

  double distance(const Vec3& x, Vec3& n) const { return distance(x, n, kAll); }
  double distance(const Vec3& x, Vec3& n, Mask mask) const;
  Mask parts_within(const Vec3& x, double margin) const;

 private:
  double part_distance(std::size_t k, const Vec3& x, Vec3& n) const {
    return std::visit([&](const auto& s) { return s.distance(x, n); }, (*parts)[k]);
  }
};

// Any signed distance: returns sdf(x) and writes the unit outward normal. This is how a
// geometry Shape plugs in, e.g.
//   SignedDistanceWall{[&shape, dim, eps](const Vec3& x, Vec3* n) {
//     *n = shape.normal(x, dim, eps); return shape.signed_distance(x, dim); }}
struct SignedDistanceWall {
  std::function<double(const Vec3&, Vec3*)> function;
  double distance(const Vec3& x, Vec3& n) const { return function(x, &n); }
};

using WallShape =
    std::variant<PlaneWall, BoxObstacle, CylinderObstacle, UnionWall, SignedDistanceWall>;

struct Wall {
  std::string name;
  WallShape shape;
  int material = 0;  // id in the contact MaterialTable
};

// sdf(x) of any wall shape, and its unit normal in *normal when not null.
double signed_distance(const WallShape& shape, const Vec3& x, Vec3* normal = nullptr);

}  // namespace washout::contact
