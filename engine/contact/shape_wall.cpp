#include "engine/contact/shape_wall.hpp"

#include <limits>
#include <memory>
#include <vector>

namespace washout::contact {
namespace {

PrimitiveWall primitive_shape(const Primitive& p, int dim) {
  switch (p.type) {
    case Primitive::Type::Box: {
      BoxObstacle box;
      box.centre = 0.5 * (p.lower + p.upper);
      box.half_size = 0.5 * (p.upper - p.lower);
      if (dim == 2) box.centre.z() = 0.0, box.half_size.z() = 0.0;  // unbounded along z
      return box;
    }
    case Primitive::Type::Cylinder: {
      CylinderObstacle cylinder;
      cylinder.centre = p.center;
      cylinder.radius = p.radius;
      if (dim == 2) {  // a disc in the x-y plane whatever the axis, as Shape has it
        cylinder.centre.z() = 0.0;
        cylinder.axis = Vec3::UnitZ();
        cylinder.half_length = 0.0;
      } else {
        cylinder.axis = Vec3::Unit(p.axis);
        cylinder.half_length = 0.5 * p.length;
      }
      return cylinder;
    }
    case Primitive::Type::Sphere:
      break;
  }
  if (dim == 2) {
    CylinderObstacle disc;
    disc.centre = Vec3(p.center.x(), p.center.y(), 0.0);
    disc.radius = p.radius;
    return disc;
  }
  return SphereObstacle{p.center, p.radius};
}

}  // namespace

WallShape wall_shape_from(const Shape& shape, int dim) {
  std::vector<PrimitiveWall> parts;
  for (const Primitive& p : shape.parts()) parts.push_back(primitive_shape(p, dim));
  if (parts.size() == 1) {
    if (auto* box = std::get_if<BoxObstacle>(&parts[0])) return *box;
    if (auto* cylinder = std::get_if<CylinderObstacle>(&parts[0])) return *cylinder;
  }
  return UnionWall{std::make_shared<const std::vector<PrimitiveWall>>(std::move(parts))};
}

}  // namespace washout::contact
