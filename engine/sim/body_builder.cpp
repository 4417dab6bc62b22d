#include "engine/sim/body_builder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/geometry/lattice_fill.hpp"
#include "engine/rigid/mass_properties.hpp"
#include "engine/rigid/quaternion_integrator.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {
namespace {

// Sub-lattice samples per particle cell and axis: 8 where affordable, fewer for large shapes so
// that the quadrature stays below a few million signed-distance evaluations.
int choose_subdivisions(const Aabb& box, int dim, double d0) {
  double cells = 1.0;
  for (int a = 0; a < dim; ++a) cells *= std::max(1.0, (box.upper[a] - box.lower[a]) / d0 + 2.0);
  const double budget = 4.0e6;
  const int s = static_cast<int>(std::floor(std::pow(budget / cells, 1.0 / dim)));
  return std::clamp(s, 1, 8);
}

rigid::PrescribedMotion prescribed_motion(const BodyMotion& motion, const Vec3& centre, int dim) {
  return [motion, centre, dim](double t) {
    const BodyPose pose = motion(t);
    rigid::BodyState s;
    s.position = centre + pose.displacement;
    s.orientation = rigid::quaternion_from_rotation_vector(pose.rotation);
    s.velocity = pose.velocity;
    s.angular_velocity = pose.angular_velocity;
    if (dim == 2) {
      s.position.z() = s.velocity.z() = 0.0;
      s.angular_velocity.x() = s.angular_velocity.y() = 0.0;
    }
    return s;
  };
}

}  // namespace

SolidGeometry integrate_solid(const Shape& shape, int dim, double d0) {
  SolidGeometry g;
  if (shape.empty()) return g;
  const Aabb box = shape.bounds(dim);
  g.subdivisions = choose_subdivisions(box, dim, d0);
  const double ds = d0 / g.subdivisions;
  // Samples at (i + 1/2) ds: the particle lattice's cell faces (multiples of d0) are sub-lattice
  // faces too, so a box on lattice planes is integrated exactly.
  long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int a = 0; a < dim; ++a) {
    lo[a] = static_cast<long>(std::floor(box.lower[a] / ds)) - 1;
    hi[a] = static_cast<long>(std::ceil(box.upper[a] / ds)) + 1;
  }
  // Moments about the box centre, then moved to the centroid (keeps the sums well scaled).
  const Vec3 origin = 0.5 * (box.lower + box.upper);
  double count = 0.0;
  Vec3 first = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (long k = lo[2]; k <= hi[2]; ++k)
    for (long j = lo[1]; j <= hi[1]; ++j)
      for (long i = lo[0]; i <= hi[0]; ++i) {
        const Vec3 x((i + 0.5) * ds, (j + 0.5) * ds, dim == 3 ? (k + 0.5) * ds : 0.0);
        if (!(shape.signed_distance(x, dim) < 0.0)) continue;
        Vec3 r = x - origin;
        if (dim == 2) r.z() = 0.0;
        count += 1.0;
        first += r;
        second += r * r.transpose();
      }
  if (count == 0.0) return g;
  const double cell = std::pow(ds, dim);
  g.volume = count * cell;
  const Vec3 mean = first / count;
  g.centroid = origin + mean;
  if (dim == 2) g.centroid.z() = 0.0;
  const Eigen::Matrix3d central = cell * (second - count * mean * mean.transpose());
  g.inertia_per_density = central.trace() * Eigen::Matrix3d::Identity() - central;
  // Each sample's own cell: a cube of side ds (ds^2/6 about each axis), or in 2D a square lamina
  // (ds^2/12 about x and y, ds^2/6 about z).
  const double d2 = ds * ds;
  const Vec3 own = dim == 3 ? Vec3::Constant(d2 / 6.0) : Vec3(d2 / 12.0, d2 / 12.0, d2 / 6.0);
  g.inertia_per_density += (g.volume * own).asDiagonal();
  return g;
}

BuiltBody build_body(const BodySpec& spec, int dim, double d0, int layers) {
  BuiltBody built;
  const std::string what = "body '" + spec.name + "' " + spec.shape.describe();
  built.solid = integrate_solid(spec.shape, dim, d0);
  if (!(built.solid.volume > 0.0)) throw SceneError(what + " has no volume", spec.where, "shape");
  const std::vector<Vec3> points = lattice_points_inside(spec.shape, dim, d0, layers * d0);
  if (points.empty())
    throw SceneError(what + " holds no particle: it is thinner than d0", spec.where, "d0");
  const double mass = spec.mass > 0.0 ? spec.mass : spec.density * built.solid.volume;
  if (!(mass > 0.0)) throw SceneError(what + " needs a positive density or mass", spec.where);

  // Surface particles: those with a lattice neighbour outside the shape. Each exposed cell face
  // f (outward e_f, area d0^(dim-1)) stands for its projection on the true surface, whose normal
  // n_f is taken at the face centre: the particle's n dS is sum_f n_f (e_f . n_f) d0^(dim-1).
  // This is exact on a flat face at any angle to the lattice, and on curved faces it is the
  // divergence theorem over the staircase of cells (with the normal at the particle instead of
  // the face centres a sphere's area would come out short by O(d0/R): 10 % at R = 4 d0).
  const double eps = 1e-9 * d0;
  const double face = dim == 3 ? d0 * d0 : d0;
  std::vector<Vec3> vector_area(points.size(), Vec3::Zero());
  std::vector<std::uint8_t> on_surface(points.size(), 0);
  Vec3 open = Vec3::Zero();
  double total = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3& x = points[k];
    for (int a = 0; a < dim; ++a)
      for (double side : {-1.0, 1.0}) {
        const Vec3 out = side * Vec3::Unit(a);
        if (spec.shape.signed_distance(x + d0 * out, dim) < -eps) continue;
        on_surface[k] = 1;
        const Vec3 n_face = spec.shape.normal(x + 0.5 * d0 * out, dim, 0.25 * d0);
        vector_area[k] += std::max(0.0, out.dot(n_face)) * face * n_face;
      }
    open += vector_area[k];
    total += vector_area[k].norm();
  }
  // The projection leaves the surface open by O(d0^2) of its area; a pressure level P0 would
  // then push the body with P0 |sum n dS|. Closing it (each particle gives back its share of
  // the sum) makes a uniform pressure exert no force, however deep the body sits.
  for (std::size_t k = 0; k < points.size() && total > 0.0; ++k)
    vector_area[k] -= vector_area[k].norm() / total * open;

  rigid::BodyParticles particles;
  particles.dim = dim;
  particles.spacing = d0;
  particles.particle_mass = mass / static_cast<double>(points.size());  // replaced below
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3& x = points[k];
    // The wall treatment's normal (as for walls), and the load's n dS.
    Vec3 normal = spec.shape.normal(x, dim, 0.25 * d0);
    const double area = vector_area[k].norm();
    if (!(normal.squaredNorm() > 0.0))
      normal = area > 0.0 ? Vec3(vector_area[k] / area) : Vec3::UnitX();
    particles.position.push_back(x);
    particles.surface.push_back(on_surface[k]);
    particles.normal.push_back(area > 0.0 ? Vec3(vector_area[k] / area) : normal);
    particles.area.push_back(area);
    built.position.push_back(x);
    built.normal.push_back(normal);
    built.depth.push_back(-spec.shape.signed_distance(x, dim));
  }
  try {
    built.model = rigid::make_body_model(particles);
    const double density = mass / built.solid.volume;
    rigid::set_mass_properties(
        built.model, {mass, built.solid.centroid, density * built.solid.inertia_per_density});
  } catch (const std::invalid_argument& e) {
    throw SceneError(what + ": " + e.what(), spec.where);
  }
  built.model.name = spec.name;
  built.initial = rigid::initial_state(built.model);
  switch (spec.motion) {
    case BodySpec::Motion::Fixed:
      built.model.motion = rigid::MotionKind::kFixed;
      break;
    case BodySpec::Motion::Prescribed:
      built.model.motion = rigid::MotionKind::kPrescribed;
      built.model.prescribed = prescribed_motion(spec.prescribed, built.model.centre_of_mass, dim);
      built.initial = built.model.prescribed(0.0);
      break;
    case BodySpec::Motion::Dynamic:
      built.model.motion = rigid::MotionKind::kDynamic;
      built.initial.velocity = spec.velocity;
      built.initial.angular_velocity = spec.angular_velocity;
      if (dim == 2) {
        built.initial.velocity.z() = 0.0;
        built.initial.angular_velocity.x() = built.initial.angular_velocity.y() = 0.0;
      }
      break;
  }
  return built;
}

}  // namespace washout
