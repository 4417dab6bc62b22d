#include "render/camera.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace washout::render {

Camera Camera::orthographic(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                            const Eigen::Vector3d& up, double half_width, double half_height,
                            double near, double far) {
  Camera c;
  c.orthographic_ = true;
  c.eye_ = eye;
  c.target_ = target;
  c.up_ = up;
  c.half_width_ = half_width;
  c.half_height_ = half_height;
  c.near_ = near;
  c.far_ = far;
  return c;
}

Camera Camera::perspective(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                           const Eigen::Vector3d& up, double fov_y_deg, double aspect, double near,
                           double far) {
  Camera c;
  c.orthographic_ = false;
  c.eye_ = eye;
  c.target_ = target;
  c.up_ = up;
  c.fov_y_deg_ = fov_y_deg;
  c.aspect_ = aspect;
  c.near_ = near;
  c.far_ = far;
  return c;
}

Eigen::Matrix4d Camera::view_matrix() const {
  const Eigen::Vector3d forward = (target_ - eye_).normalized();
  const Eigen::Vector3d right = forward.cross(up_).normalized();
  const Eigen::Vector3d true_up = right.cross(forward);
  const Eigen::Vector3d eye_rel = eye_ - origin();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = true_up.transpose();
  m.block<1, 3>(2, 0) = -forward.transpose();
  m(0, 3) = -right.dot(eye_rel);
  m(1, 3) = -true_up.dot(eye_rel);
  m(2, 3) = forward.dot(eye_rel);
  return m;
}

Eigen::Matrix4d Camera::projection_matrix() const {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  const double depth = far_ - near_;
  if (orthographic_) {
    p(0, 0) = 1.0 / half_width_;
    p(1, 1) = 1.0 / half_height_;
    p(2, 2) = -2.0 / depth;
    p(2, 3) = -(far_ + near_) / depth;
    p(3, 3) = 1.0;
  } else {
    const double f = 1.0 / std::tan(0.5 * fov_y_deg_ * std::numbers::pi / 180.0);
    p(0, 0) = f / aspect_;
    p(1, 1) = f;
    p(2, 2) = -(far_ + near_) / depth;
    p(2, 3) = -2.0 * far_ * near_ / depth;
    p(3, 2) = -1.0;
  }
  return p;
}

std::optional<Eigen::Vector3d> Camera::to_ndc(const Eigen::Vector3d& world) const {
  const Eigen::Vector4d rel((world - origin()).x(), (world - origin()).y(), (world - origin()).z(),
                            1.0);
  const Eigen::Vector4d clip = projection_matrix() * view_matrix() * rel;
  if (clip.w() <= 0.0) return std::nullopt;
  return Eigen::Vector3d(clip.x() / clip.w(), clip.y() / clip.w(), clip.z() / clip.w());
}

}  // namespace washout::render
