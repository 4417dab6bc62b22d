#include "engine/rigid/body_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace washout::rigid {
namespace {

void check_input(const BodyParticles& p) {
  const std::size_t n = p.position.size();
  if (p.dim != 2 && p.dim != 3) throw std::invalid_argument("rigid body: dim must be 2 or 3");
  if (n == 0) throw std::invalid_argument("rigid body: no particles");
  if (!(p.spacing > 0.0)) throw std::invalid_argument("rigid body: spacing must be > 0");
  if (!(p.particle_mass > 0.0)) throw std::invalid_argument("rigid body: particle mass <= 0");
  if (!p.surface.empty()) {
    if (p.surface.size() != n || p.normal.size() != n || p.area.size() != n)
      throw std::invalid_argument("rigid body: surface mask, normals and areas need n entries");
  }
}

// Inertia of the particles about the centre of mass, body frame (METHOD.md Rigid bodies: "from
// its particles"). Each particle is a point mass; with ParticleInertia::kCell it also carries
// its own cube (3D) or square (2D) of side d0, m d0^2/6 about each of its own axes, which makes
// the lattice sum exact for a box: sum_k (k d0 - a/2 + d0/2)^2 = n (a^2 - d0^2)/12.
Eigen::Matrix3d particle_inertia(const BodyParticles& p, const Vec3Array& r) {
  const std::size_t n = r.size();
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    xx += r.x[i] * r.x[i];
    yy += r.y[i] * r.y[i];
    zz += r.z[i] * r.z[i];
    xy += r.x[i] * r.y[i];
    xz += r.x[i] * r.z[i];
    yz += r.y[i] * r.z[i];
  }
  const double m = p.particle_mass;
  Eigen::Matrix3d inertia;
  inertia << m * (yy + zz), -m * xy, -m * xz,  //
      -m * xy, m * (xx + zz), -m * yz,         //
      -m * xz, -m * yz, m * (xx + yy);
  if (p.particle_inertia == ParticleInertia::kCell) {
    const double d2 = p.spacing * p.spacing;
    const double total = m * static_cast<double>(n);
    if (p.dim == 3) {
      inertia += Eigen::Matrix3d::Identity() * (total * d2 / 6.0);
    } else {
      // A square lamina of side d0: d0^2/12 about its in-plane axes, d0^2/6 about z.
      inertia += Eigen::Vector3d(d2 / 12.0, d2 / 12.0, d2 / 6.0).asDiagonal() * total;
    }
  }
  return inertia;
}

}  // namespace

BodyModel make_body_model(const BodyParticles& p) {
  check_input(p);
  const std::size_t n = p.position.size();
  BodyModel model;
  model.dim = p.dim;
  model.spacing = p.spacing;
  model.contact_radius = 0.5 * p.spacing;
  model.particle_mass = p.particle_mass;
  model.mass = p.particle_mass * static_cast<double>(n);

  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) sum += p.position[i];
  model.centre_of_mass = sum / static_cast<double>(n);
  if (p.dim == 2) model.centre_of_mass.z() = 0.0;

  model.offset.resize(n);
  double max_r2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 r = p.position[i] - model.centre_of_mass;
    if (p.dim == 2) r.z() = 0.0;
    model.offset.set(i, r);
    max_r2 = std::max(max_r2, r.squaredNorm());
  }
  model.bounding_radius = std::sqrt(max_r2) + model.contact_radius;

  set_inertia(model, particle_inertia(p, model.offset));

  for (std::size_t i = 0; i < n; ++i) {
    const bool on_surface = p.surface.empty() || p.surface[i] != 0;
    if (!on_surface) continue;
    model.contact_index.push_back(static_cast<std::int32_t>(i));
    model.contact_offset.push_back(model.offset[i]);
    if (p.surface.empty()) continue;
    Vec3 normal = p.normal[i];
    if (p.dim == 2) normal.z() = 0.0;
    const double length = normal.norm();
    if (!(length > 0.0)) throw std::invalid_argument("rigid body: surface normal of length 0");
    model.surface_index.push_back(static_cast<std::int32_t>(i));
    model.surface_offset.push_back(model.offset[i]);
    model.surface_normal.push_back(normal / length);
    model.surface_area.push_back(p.area[i]);
  }
  return model;
}

void set_inertia(BodyModel& model, const Eigen::Matrix3d& inertia) {
  model.inertia = inertia;
  if (model.dim == 3) {
    if (!(std::abs(inertia.determinant()) > 0.0))
      throw std::invalid_argument("rigid body: singular inertia tensor");
    model.inertia_inverse = inertia.inverse();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
    model.principal_moments = eigen.eigenvalues();
    model.principal_axes = eigen.eigenvectors();
    if (model.principal_axes.determinant() < 0.0) model.principal_axes.col(2) *= -1.0;
  } else {
    const double izz = inertia(2, 2);
    if (!(izz > 0.0)) throw std::invalid_argument("rigid body: I_zz must be > 0");
    model.inertia_inverse = Eigen::Matrix3d::Zero();
    model.inertia_inverse(2, 2) = 1.0 / izz;
    model.principal_moments = Vec3(inertia(0, 0), inertia(1, 1), izz);
    model.principal_axes = Eigen::Matrix3d::Identity();
  }
}

}  // namespace washout::rigid
