#include "render/camera_fit.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "render/render_error.hpp"

namespace washout::render {
namespace {

// Fraction of the view the scene may fill, so it never touches the image border.
constexpr double kFill = 0.94;

struct Basis {
  Eigen::Vector3d right, up, forward;
};

// Camera axes looking along forward; an up vector parallel to forward is replaced.
Basis basis_for(const Eigen::Vector3d& forward, Eigen::Vector3d up) {
  const Eigen::Vector3d f = forward.normalized();
  if (f.cross(up).norm() < 1e-9 * up.norm() || up.norm() == 0.0) {
    up = std::abs(f.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
  }
  const Eigen::Vector3d r = f.cross(up).normalized();
  return {r, r.cross(f), f};
}

std::array<Eigen::Vector3d, 8> corners(const SceneBounds& b) {
  std::array<Eigen::Vector3d, 8> c;
  for (int i = 0; i < 8; ++i) {
    c[i] = Eigen::Vector3d(i & 1 ? b.hi.x() : b.lo.x(), i & 2 ? b.hi.y() : b.lo.y(),
                           i & 4 ? b.hi.z() : b.lo.z());
  }
  return c;
}

Camera fit_orthographic(const SceneBounds& bounds, const Eigen::Vector3d& forward,
                        const Eigen::Vector3d& up, double aspect) {
  const Basis basis = basis_for(forward, up);
  const Eigen::Vector3d center = bounds.center();
  double half_w = 0.0, half_h = 0.0, depth = 0.0;
  for (const Eigen::Vector3d& c : corners(bounds)) {
    const Eigen::Vector3d d = c - center;
    half_w = std::max(half_w, std::abs(d.dot(basis.right)));
    half_h = std::max(half_h, std::abs(d.dot(basis.up)));
    depth = std::max(depth, std::abs(d.dot(basis.forward)));
  }
  half_w /= kFill;
  half_h /= kFill;
  if (half_w <= 0.0 && half_h <= 0.0) half_w = half_h = 1.0;
  // Keep the aspect ratio of the drawing area: widen whichever side is too narrow.
  if (half_w < half_h * aspect) {
    half_w = half_h * aspect;
  } else {
    half_h = half_w / aspect;
  }
  // Stand well outside the box so that the sphere caps in front stay inside the near plane.
  const double margin = 2.0 * std::max({half_w, half_h, depth});
  const double distance = depth + margin;
  const Eigen::Vector3d eye = center - basis.forward * distance;
  return Camera::orthographic(eye, center, basis.up, half_w, half_h, 0.25 * margin,
                              distance + depth + margin);
}

// Near and far planes that hold every corner of the box, seen from eye along forward.
std::pair<double, double> depth_range(const SceneBounds& bounds, const Eigen::Vector3d& eye,
                                      const Eigen::Vector3d& forward) {
  double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
  for (const Eigen::Vector3d& c : corners(bounds)) {
    const double depth = (c - eye).dot(forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  const double far = std::max(1.05 * farthest, 1e-6);
  const double near = std::max(0.5 * nearest, 1e-4 * far);
  return {near, far};
}

Camera fit_perspective(const SceneBounds& bounds, const Eigen::Vector3d& forward,
                       const Eigen::Vector3d& up, double fov_y_deg, double aspect) {
  const Basis basis = basis_for(forward, up);
  const Eigen::Vector3d center = bounds.center();
  const double tan_y = std::tan(0.5 * fov_y_deg * std::numbers::pi / 180.0) * kFill;
  const double tan_x = tan_y * aspect;
  // Each corner needs the eye at least this far back along -forward to fit in the view.
  double distance = 0.0, behind = 0.0;
  for (const Eigen::Vector3d& c : corners(bounds)) {
    const Eigen::Vector3d d = c - center;
    const double along = d.dot(basis.forward);
    distance = std::max({distance, std::abs(d.dot(basis.right)) / tan_x - along,
                         std::abs(d.dot(basis.up)) / tan_y - along});
    behind = std::max(behind, -along);
  }
  distance = std::max(distance, behind + 0.05 * bounds.size().norm() + 1e-9);
  const Eigen::Vector3d eye = center - basis.forward * distance;
  const auto [near, far] = depth_range(bounds, eye, basis.forward);
  return Camera::perspective(eye, center, basis.up, fov_y_deg, aspect, near, far);
}

Eigen::Vector3d vec(const double v[3]) { return {v[0], v[1], v[2]}; }

}  // namespace

void validate_camera_spec(const CameraSpec& spec) {
  if (spec.region_components != 0) {
    if (spec.region_components != 2 && spec.region_components != 3)
      throw RenderError("camera region needs 2 (2D) or 3 (3D) components for min and max");
    for (int a = 0; a < spec.region_components; ++a)
      if (!(spec.region_max[a] > spec.region_min[a]))
        throw RenderError(std::string("camera region: max must exceed min along ") + char('x' + a));
  }
  if (spec.explicit_pose) {
    if ((vec(spec.position) - vec(spec.target)).norm() == 0.0) {
      throw RenderError("camera position and target must differ");
    }
    if (!(spec.fov_deg > 0.0 && spec.fov_deg < 180.0)) {
      throw RenderError("camera fov must be between 0 and 180 degrees");
    }
    return;
  }
  const std::string& p = spec.preset;
  if (p != "auto" && p != "side" && p != "top" && p != "perspective") {
    throw RenderError("unknown camera preset '" + p + "' (choose auto, side, top or perspective)");
  }
  if (!(spec.fov_deg > 0.0 && spec.fov_deg < 180.0)) {
    throw RenderError("camera fov must be between 0 and 180 degrees");
  }
}

Camera fit_camera(const CameraSpec& spec, int dim, const SceneBounds& particles, double aspect) {
  validate_camera_spec(spec);
  if (spec.region_components != 0 && spec.region_components != dim)
    throw RenderError("camera region has " + std::to_string(spec.region_components) +
                      " components; this scene is " + std::to_string(dim) + "D");
  SceneBounds bounds = particles;
  if (spec.region_components != 0) {
    bounds.lo = Eigen::Vector3d(spec.region_min[0], spec.region_min[1], 0.0);
    bounds.hi = Eigen::Vector3d(spec.region_max[0], spec.region_max[1], 0.0);
    if (dim == 3) bounds.lo.z() = spec.region_min[2], bounds.hi.z() = spec.region_max[2];
  }
  if (dim == 2)
    return fit_orthographic(bounds, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(), aspect);
  if (spec.explicit_pose) {
    const Eigen::Vector3d eye = vec(spec.position), target = vec(spec.target);
    const Basis basis = basis_for(target - eye, vec(spec.up));
    const auto [near, far] = depth_range(particles, eye, basis.forward);
    return Camera::perspective(eye, target, basis.up, spec.fov_deg, aspect, near, far);
  }
  if (spec.preset == "side") {
    return fit_orthographic(bounds, Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), aspect);
  }
  if (spec.preset == "top") {
    return fit_orthographic(bounds, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(), aspect);
  }
  // The 3/4 view: from the -y side, slightly upstream and above, looking at the box centre.
  const Eigen::Vector3d from(-0.35, -1.0, 0.55);
  return fit_perspective(bounds, -from, Eigen::Vector3d::UnitZ(), spec.fov_deg, aspect);
}

}  // namespace washout::render
