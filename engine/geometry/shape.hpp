#pragma once
// Solid shapes as signed distance functions (negative inside): boxes, cylinders and their
// unions. Walls, obstacles, fluid regions and rigid bodies are all built from these.
// In 2D the z coordinate is ignored: a box is a rectangle, a cylinder with axis z a disc.
#include <string>
#include <vector>

#include "engine/core/vec3.hpp"

namespace washout {

struct Aabb {
  Vec3 lower, upper;
};

struct Primitive {
  enum class Type { Box, Cylinder, Sphere };
  Type type = Type::Box;
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  // Box
  Vec3 center = Vec3::Zero();                       // Cylinder, Sphere
  double radius = 0.0;                              // Cylinder, Sphere
  double length = 0.0;                              // Cylinder, along `axis`
  int axis = 2;                                     // Cylinder axis: 0 x, 1 y, 2 z

  double signed_distance(const Vec3& p, int dim) const;
  Aabb bounds(int dim) const;
};

// A union of primitives, optionally translated (moving walls, bodies use their own frame).
class Shape {
 public:
  Shape() = default;
  explicit Shape(std::vector<Primitive> parts) : parts_(std::move(parts)) {}
  static Shape box(const Vec3& lower, const Vec3& upper);
  static Shape cylinder(const Vec3& center, double radius, double length, int axis);
  static Shape sphere(const Vec3& center, double radius);

  void add(const Shape& other);
  bool empty() const { return parts_.empty(); }
  const std::vector<Primitive>& parts() const { return parts_; }

  double signed_distance(const Vec3& p, int dim) const;
  // Outward unit normal (gradient of the signed distance), by central differences of width eps.
  Vec3 normal(const Vec3& p, int dim, double eps) const;
  Aabb bounds(int dim) const;
  double volume_estimate(int dim, double spacing) const;  // by lattice count, for checks
  std::string describe() const;

 private:
  std::vector<Primitive> parts_;
};

}  // namespace washout
