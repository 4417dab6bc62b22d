#pragma once
// A rigid body from a scene shape (METHOD.md Rigid bodies; docs/bodies.md "How a body is
// built"). The fluid sees a body as a wall that moves: like a wall it keeps as particles only
// the outer layers of its lattice fill (as deep as the kernel reaches), with unit normals
// pointing into the fluid and their distance to the surface. Its outermost layer is its
// surface: it carries the areas dS of the hydrodynamic load and touches other things in
// contact. Mass, centre of mass and inertia are those of the whole solid, integrated from the
// shape on a lattice finer than the particles' (exact for boxes on lattice planes).
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/geometry/shape.hpp"
#include "engine/model/model.hpp"
#include "engine/rigid/body_model.hpp"
#include "engine/rigid/body_state.hpp"

namespace washout {

// Volume, centroid and inertia per unit density of a solid shape, by the midpoint rule on the
// sub-lattice of spacing d0/s (s up to 8, fewer where the shape is large), each sample a cell
// with its own moment (as the particles' ParticleInertia::kCell). 2D: area, and the inertia of
// a lamina (only I_zz matters).
struct SolidGeometry {
  double volume = 0.0;  // [m^dim]
  Vec3 centroid = Vec3::Zero();
  Eigen::Matrix3d inertia_per_density = Eigen::Matrix3d::Zero();  // about the centroid [m^(dim+2)]
  int subdivisions = 1;                                           // s
};
SolidGeometry integrate_solid(const Shape& shape, int dim, double d0);

struct BuiltBody {
  rigid::BodyModel model;      // offsets of its particles, solid mass properties, surface, motion
  rigid::BodyState initial;    // X = centre of mass, q = identity, the given T and w
  std::vector<Vec3> position;  // its particles at t = 0 (lattice points), in model.offset order
  std::vector<Vec3> normal;    // unit, out of the body, at t = 0 (= body frame)
  std::vector<double> depth;   // distance from each particle to the surface
  SolidGeometry solid;
};

// `layers` is the number of lattice layers kept as particles (walls use the same). Throws
// SceneError (with the body's location) for a body thinner than the lattice or without mass.
BuiltBody build_body(const BodySpec& spec, int dim, double d0, int layers);

}  // namespace washout
