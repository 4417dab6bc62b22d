#include "render/scene_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace washout::render {

namespace {

// Box of the finite centres of the particles that pass keep(i); nullopt if none does.
template <class Keep>
std::optional<SceneBounds> bounds_of(const ParticleView& view, double pad, Keep keep) {
  const double inf = std::numeric_limits<double>::infinity();
  SceneBounds b;
  b.lo = Eigen::Vector3d::Constant(inf);
  b.hi = Eigen::Vector3d::Constant(-inf);
  bool any = false;
  for (std::size_t i = 0; i < view.count; ++i) {
    if (!keep(i)) continue;
    for (int axis = 0; axis < 3; ++axis) {
      const double x = axis < view.dim ? view.position(i, axis) : 0.0;
      if (!std::isfinite(x)) continue;  // a diverged particle must not blow up the camera
      b.lo[axis] = std::min(b.lo[axis], x);
      b.hi[axis] = std::max(b.hi[axis], x);
      any = true;
    }
  }
  if (!any) return std::nullopt;
  for (int axis = 0; axis < 3; ++axis) {
    if (b.lo[axis] > b.hi[axis]) b.lo[axis] = b.hi[axis] = 0.0;
  }
  b.lo.array() -= pad;
  b.hi.array() += pad;
  if (view.dim == 2) b.lo.z() = b.hi.z() = 0.0;
  return b;
}

}  // namespace

SceneBounds particle_bounds(const ParticleView& view, double pad) {
  // Retired fluid (left the domain) is not drawn and does not stretch the picture.
  return bounds_of(view, pad,
                   [&](std::size_t i) {
                     return !view.kind ||
                            view.kind[i] != static_cast<std::uint8_t>(ParticleKind::Retired);
                   })
      .value_or(SceneBounds{});
}

std::optional<SceneBounds> fluid_bounds(const ParticleView& view, double pad) {
  return bounds_of(view, pad, [&](std::size_t i) {
    return !view.kind || view.kind[i] == static_cast<std::uint8_t>(ParticleKind::Fluid);
  });
}

double particle_radius(const ParticleView& view) {
  if (view.d0 > 0.0) return 0.5 * view.d0;
  const SceneBounds b = particle_bounds(view, 0.0);
  const double n = static_cast<double>(std::max<std::size_t>(view.count, 1));
  double measure = 1.0;
  double largest = 0.0;
  for (int axis = 0; axis < view.dim; ++axis) {
    measure *= std::max(b.size()[axis], 0.0);
    largest = std::max(largest, b.size()[axis]);
  }
  const double spacing = std::pow(measure / n, 1.0 / view.dim);
  if (spacing > 0.0) return 0.5 * spacing;
  if (largest > 0.0) return 0.01 * largest;
  return 0.5;
}

}  // namespace washout::render
