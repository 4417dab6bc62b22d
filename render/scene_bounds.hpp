#pragma once
// The box around every particle of a frame (all kinds), and the drawn particle radius.
#include <Eigen/Core>
#include <optional>

#include "engine/core/particle_view.hpp"

namespace washout::render {

struct SceneBounds {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
  Eigen::Vector3d center() const { return 0.5 * (lo + hi); }
  Eigen::Vector3d size() const { return hi - lo; }
};

// Box of the particle centres (retired fluid left out) grown by pad on every side; z is 0 in 2D.
SceneBounds particle_bounds(const ParticleView& view, double pad);

// Box of the fluid particles only (kind 0), grown by pad; nullopt without fluid.
std::optional<SceneBounds> fluid_bounds(const ParticleView& view, double pad);

// World radius of a drawn particle: d0 / 2, so that neighbours at spacing d0 touch. A view
// without d0 gets the spacing estimated from its bounding box and count.
double particle_radius(const ParticleView& view);

}  // namespace washout::render
