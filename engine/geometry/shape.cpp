#include "engine/geometry/shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace washout {
namespace {

// Exact signed distance of an axis-aligned box.
double box_distance(const Vec3& p, const Vec3& lower, const Vec3& upper, int dim) {
  double outside2 = 0.0, inside = std::numeric_limits<double>::lowest();
  for (int a = 0; a < dim; ++a) {
    const double c = 0.5 * (lower[a] + upper[a]), e = 0.5 * (upper[a] - lower[a]);
    const double q = std::abs(p[a] - c) - e;
    if (q > 0) outside2 += q * q;
    inside = std::max(inside, q);
  }
  return outside2 > 0 ? std::sqrt(outside2) : inside;
}

}  // namespace

double Primitive::signed_distance(const Vec3& p, int dim) const {
  switch (type) {
    case Type::Box:
      return box_distance(p, lower, upper, dim);
    case Type::Sphere: {
      Vec3 d = p - center;
      if (dim == 2) d.z() = 0;
      return d.norm() - radius;
    }
    case Type::Cylinder: {
      Vec3 d = p - center;
      if (dim == 2) {  // a disc in the x-y plane whatever the axis
        d.z() = 0;
        return d.norm() - radius;
      }
      const double along = d[axis];
      d[axis] = 0;
      const double radial = d.norm() - radius, axial = std::abs(along) - 0.5 * length;
      const double out = std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
      return out > 0 ? out : std::max(radial, axial);
    }
  }
  return std::numeric_limits<double>::max();
}

Aabb Primitive::bounds(int dim) const {
  Aabb b;
  if (type == Type::Box) {
    b = {lower, upper};
  } else {
    b.lower = center - Vec3::Constant(radius);
    b.upper = center + Vec3::Constant(radius);
    if (type == Type::Cylinder && dim == 3) {
      b.lower[axis] = center[axis] - 0.5 * length;
      b.upper[axis] = center[axis] + 0.5 * length;
    }
  }
  if (dim == 2) b.lower.z() = b.upper.z() = 0.0;
  return b;
}

Shape Shape::box(const Vec3& lower, const Vec3& upper) {
  Primitive p;
  p.type = Primitive::Type::Box;
  p.lower = lower.cwiseMin(upper);
  p.upper = lower.cwiseMax(upper);
  return Shape({p});
}

Shape Shape::cylinder(const Vec3& center, double radius, double length, int axis) {
  Primitive p;
  p.type = Primitive::Type::Cylinder;
  p.center = center;
  p.radius = radius;
  p.length = length;
  p.axis = axis;
  return Shape({p});
}

Shape Shape::sphere(const Vec3& center, double radius) {
  Primitive p;
  p.type = Primitive::Type::Sphere;
  p.center = center;
  p.radius = radius;
  return Shape({p});
}

void Shape::add(const Shape& other) {
  parts_.insert(parts_.end(), other.parts_.begin(), other.parts_.end());
}

double Shape::signed_distance(const Vec3& p, int dim) const {
  double d = std::numeric_limits<double>::max();
  for (const auto& part : parts_) d = std::min(d, part.signed_distance(p, dim));
  return d;
}

Vec3 Shape::normal(const Vec3& p, int dim, double eps) const {
  Vec3 g = Vec3::Zero();
  for (int a = 0; a < dim; ++a) {
    Vec3 e = Vec3::Zero();
    e[a] = eps;
    g[a] = signed_distance(p + e, dim) - signed_distance(p - e, dim);
  }
  const double n = g.norm();
  return n > 0 ? Vec3(g / n) : Vec3::Zero();
}

Aabb Shape::bounds(int dim) const {
  Aabb b{Vec3::Constant(std::numeric_limits<double>::max()),
         Vec3::Constant(std::numeric_limits<double>::lowest())};
  for (const auto& part : parts_) {
    const Aabb pb = part.bounds(dim);
    b.lower = b.lower.cwiseMin(pb.lower);
    b.upper = b.upper.cwiseMax(pb.upper);
  }
  return b;
}

double Shape::volume_estimate(int dim, double spacing) const {
  const Aabb b = bounds(dim);
  long count = 0;
  const double s = spacing;
  for (double z = (dim == 3 ? b.lower.z() + 0.5 * s : 0.0); z < (dim == 3 ? b.upper.z() : 1.0);
       z += (dim == 3 ? s : 2.0))
    for (double y = b.lower.y() + 0.5 * s; y < b.upper.y(); y += s)
      for (double x = b.lower.x() + 0.5 * s; x < b.upper.x(); x += s)
        if (signed_distance({x, y, z}, dim) < 0) ++count;
  return count * std::pow(s, dim);
}

std::string Shape::describe() const {
  std::ostringstream o;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const auto& p = parts_[k];
    if (k) o << " + ";
    if (p.type == Primitive::Type::Box)
      o << "box[(" << p.lower.transpose() << ") .. (" << p.upper.transpose() << ")]";
    else if (p.type == Primitive::Type::Cylinder)
      o << "cylinder[c=(" << p.center.transpose() << ") r=" << p.radius << "]";
    else
      o << "sphere[c=(" << p.center.transpose() << ") r=" << p.radius << "]";
  }
  return o.str();
}

}  // namespace washout
