#pragma once
// A fixed camera: where it stands, what it looks at, and how it projects (orthographic or
// perspective). Matrices follow OpenGL conventions (right-handed camera space looking down -z,
// clip space in [-1, 1]). Geometry is sent to the GPU relative to origin() so that float
// precision is spent near the scene, not near the world origin.
#include <Eigen/Core>
#include <optional>

namespace washout::render {

class Camera {
 public:
  static Camera orthographic(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                             const Eigen::Vector3d& up, double half_width, double half_height,
                             double near, double far);
  static Camera perspective(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                            const Eigen::Vector3d& up, double fov_y_deg, double aspect, double near,
                            double far);

  bool is_orthographic() const { return orthographic_; }
  const Eigen::Vector3d& eye() const { return eye_; }
  const Eigen::Vector3d& target() const { return target_; }
  const Eigen::Vector3d& origin() const { return target_; }

  // Maps (world point - origin()) to camera space.
  Eigen::Matrix4d view_matrix() const;
  Eigen::Matrix4d projection_matrix() const;

  // Normalised device coordinates (x, y in [-1, 1] on screen, z depth) of a world point;
  // nullopt when the point is behind a perspective camera.
  std::optional<Eigen::Vector3d> to_ndc(const Eigen::Vector3d& world) const;

 private:
  Camera() = default;
  bool orthographic_ = true;
  Eigen::Vector3d eye_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitZ();
  double half_width_ = 1.0, half_height_ = 1.0;  // orthographic
  double fov_y_deg_ = 35.0, aspect_ = 1.0;       // perspective
  double near_ = 0.1, far_ = 100.0;
};

}  // namespace washout::render
