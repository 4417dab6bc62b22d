#pragma once
// Simple bodies filled with particles on a cell-centred lattice of spacing d0, with their outer
// layer marked as surface: for tests, benchmarks and quick scenes (the geometry module builds a
// scene's bodies from its shapes). Particle mass = density d0^dim (2D: per metre of thickness).
#include "engine/core/vec3.hpp"
#include "engine/rigid/body_model.hpp"

namespace washout::rigid {

// Box [lower, upper] (2D: x-y rectangle, z ignored); its sides are rounded to whole cells.
// Surface: the outer layer; a particle's normal and area are its vector area summed over the
// faces it lies on (n dS = sum_faces n_face d0^2; d0 in 2D), so sum n dS = 0 exactly.
BodyParticles lattice_box(int dim, double spacing, const Vec3& lower, const Vec3& upper,
                          double density);

// Sphere (3D) or disc (2D) of radius R centred on a lattice point. Surface: particles with a
// lattice neighbour outside; radial normals; areas 4 pi R^2 (2 pi R in 2D) shared equally.
BodyParticles lattice_ball(int dim, double spacing, const Vec3& centre, double radius,
                           double density);

// Solid cylinder (3D) along z: its axis on a lattice line, its length rounded to whole cells
// (cell-centred layers); no surface description.
BodyParticles lattice_cylinder(double spacing, const Vec3& centre, double radius, double length,
                               double density);

}  // namespace washout::rigid
