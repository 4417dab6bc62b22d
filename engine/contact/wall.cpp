#include "engine/contact/wall.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace washout::contact {
namespace {

double sign_of(double v) { return v < 0.0 ? -1.0 : 1.0; }

}  // namespace

double BoxObstacle::distance(const Vec3& x, Vec3& n) const {
  const Vec3 p = rotation.transpose() * (x - centre);
  Vec3 q = p.cwiseAbs() - half_size;
  if (half_size.z() <= 0.0) q.z() = -std::numeric_limits<double>::infinity();
  Vec3 local = Vec3::Zero();
  double d;
  if ((q.x() > 0.0) + (q.y() > 0.0) + (q.z() > 0.0) > 1) {  // beyond an edge or a corner
    const Vec3 outside = q.cwiseMax(0.0);
    d = outside.norm();
    for (int k = 0; k < 3; ++k) local[k] = sign_of(p[k]) * outside[k] / d;
  } else {  // inside, or beyond one face only: the nearest face (the root of q_k^2 is q_k)
    int k;
    d = q.maxCoeff(&k);
    local[k] = sign_of(p[k]);
  }
  n = rotation * local;
  return d;
}

double CylinderObstacle::distance(const Vec3& x, Vec3& n) const {
  const Vec3 p = x - centre;
  const double along = p.dot(axis);
  const Vec3 radial = p - along * axis;
  const double rho = radial.norm();
  Vec3 radial_unit;
  if (rho > 0.0) {
    radial_unit = radial / rho;
  } else {  // on the axis: any direction across it
    radial_unit = axis.unitOrthogonal();
  }
  const double q_radial = rho - radius;
  const double q_axial =
      half_length > 0.0 ? std::abs(along) - half_length : -std::numeric_limits<double>::infinity();
  const Vec3 axial_unit = sign_of(along) * axis;
  if (q_radial > 0.0 || q_axial > 0.0) {
    const double a = std::max(q_radial, 0.0), b = std::max(q_axial, 0.0);
    const double d = std::hypot(a, b);
    n = (a * radial_unit + b * axial_unit) / d;
    return d;
  }
  if (q_radial > q_axial) {
    n = radial_unit;
    return q_radial;
  }
  n = axial_unit;
  return q_axial;
}

double UnionWall::distance(const Vec3& x, Vec3& n, Mask mask) const {
  const bool every = parts->size() > 32;  // no mask bit for parts past 32: all of them
  double nearest = std::numeric_limits<double>::max();
  Vec3 part_normal;
  for (std::size_t k = 0; k < parts->size(); ++k) {
    if (!every && !(mask >> k & 1u)) continue;
    const double d = part_distance(k, x, part_normal);
    if (d < nearest) {
      nearest = d;
      n = part_normal;
    }
  }
  return nearest;
}

UnionWall::Mask UnionWall::parts_within(const Vec3& x, double margin) const {
  if (parts->size() > 32) return kAll;
  std::array<double, 32> d;
  Vec3 n;
  double nearest = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k < parts->size(); ++k) {
    d[k] = part_distance(k, x, n);
    nearest = std::min(nearest, d[k]);
  }
  Mask mask = 0;
  for (std::size_t k = 0; k < parts->size(); ++k)
    if (d[k] <= nearest + 2.0 * margin) mask |= Mask(1) << k;
  return mask;
}

double signed_distance(const WallShape& shape, const Vec3& x, Vec3* normal) {
  Vec3 n;
  const double d = std::visit([&](const auto& s) { return s.distance(x, n); }, shape);
  if (normal) *normal = n;
  return d;
}

}  // namespace washout::contact
