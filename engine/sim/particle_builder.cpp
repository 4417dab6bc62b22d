#include "engine/sim/particle_builder.hpp"

#include <cmath>
#include <sstream>
#include <unordered_set>

#include "engine/geometry/lattice_fill.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {
namespace {

// Integer lattice coordinates packed in one key, to keep particles of different shapes apart.
std::uint64_t lattice_key(const Vec3& x, double d0) {
  auto c = [&](double v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / d0)) + (1 << 20)) &
           0x1FFFFF;
  };
  return c(x[0]) | (c(x[1]) << 21) | (c(x[2]) << 42);
}

std::string format_length(double v) {
  std::ostringstream o;
  o << v << " m";
  return o.str();
}

std::string format_point(const Vec3& x, int dim) {
  std::ostringstream o;
  o << "(" << x.x() << ", " << x.y();
  if (dim == 3) o << ", " << x.z();
  o << ") m";
  return o.str();
}

// Bodies must start clear of the walls and of each other: no particle of one inside the shape
// of another (touching is allowed: a girder resting on its pier).
void check_body_overlaps(const Model& model, const BuiltParticles& out) {
  const int dim = model.params.dim;
  const Particles& p = out.particles;
  for (std::size_t b = 0; b < out.bodies.size(); ++b) {
    const BodySpec& body = model.bodies[b];
    for (const Vec3& x : out.bodies[b].position) {
      for (const auto& wall : model.walls)
        if (wall.shape.signed_distance(x, dim) < 0.0)
          throw SceneError("body '" + body.name + "' overlaps wall '" + wall.name + "' at " +
                               format_point(x, dim),
                           body.where, "shape");
      for (std::size_t c = 0; c < out.bodies.size(); ++c)
        if (c != b && model.bodies[c].shape.signed_distance(x, dim) < 0.0)
          throw SceneError("body '" + body.name + "' overlaps body '" + model.bodies[c].name +
                               "' at " + format_point(x, dim),
                           body.where, "shape");
    }
    for (std::size_t i = p.fluid_count; i < p.size(); ++i) {
      if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::RigidBody)) continue;
      if (body.shape.signed_distance(p.x(i), dim) < 0.0)
        throw SceneError("body '" + body.name + "' overlaps wall '" + model.walls[p.group[i]].name +
                             "' at " + format_point(p.x(i), dim),
                         body.where, "shape");
    }
  }
}

// Body particles after the walls: each body's outer layers, in its model's order.
void add_bodies(const Model& model, int layers, std::unordered_set<std::uint64_t>& occupied,
                BuiltParticles& out) {
  if (model.bodies.empty()) return;
  const int dim = model.params.dim;
  const double d0 = model.params.d0;
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    out.bodies.push_back(build_body(model.bodies[b], dim, d0, layers));
  check_body_overlaps(model, out);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const BuiltBody& body = out.bodies[b];
    out.body_first.push_back(out.particles.size());
    for (std::size_t k = 0; k < body.position.size(); ++k) {
      occupied.insert(lattice_key(body.position[k], d0));
      out.particles.add(ParticleKind::RigidBody, body.position[k], Vec3::Zero(),
                        static_cast<std::int32_t>(b), body.normal[k], body.depth[k]);
      out.wall_slip.push_back(model.bodies[b].slip);
    }
  }
}

}  // namespace

BuiltParticles build_particles(const Model& model) {
  const auto& prm = model.params;
  const int dim = prm.dim;
  const double d0 = prm.d0;
  const int layers = prm.wall_layer_count();
  BuiltParticles out;
  out.particles.dim = dim;
  if (model.fluids.empty())
    throw SceneError("the scene defines no fluid (add washout.fluid{...})", model.scene_path);

  std::unordered_set<std::uint64_t> occupied;
  // Fluid keeps half a spacing from walls and bodies (their surface lies d0/2 beyond their
  // outermost particles on the lattice).
  auto near_wall = [&](const Vec3& x) {
    for (const auto& wall : model.walls)
      if (wall.shape.signed_distance(x, dim) < 0.5 * d0 - 1e-9 * d0) return true;
    for (const auto& body : model.bodies)
      if (body.shape.signed_distance(x, dim) < 0.5 * d0 - 1e-9 * d0) return true;
    return false;
  };
  for (const auto& region : model.fluids) {
    std::size_t added = 0, inside_walls = 0;
    const auto points = lattice_points_inside(region.shape, dim, d0);
    for (const auto& x : points) {
      if (near_wall(x)) {
        ++inside_walls;
        continue;
      }
      if (!occupied.insert(lattice_key(x, d0)).second) continue;
      out.particles.add(ParticleKind::Fluid, x, region.velocity, -1);
      ++added;
    }
    if (added == 0) {
      std::string why = points.empty()
                            ? "it is smaller than the particle spacing d0 = " + format_length(d0)
                            : "all of its " + std::to_string(points.size()) +
                                  " lattice points lie inside or against walls or bodies";
      throw SceneError("fluid region " + region.shape.describe() + " holds no particle: " + why,
                       region.where, "d0");
    }
  }

  for (std::size_t w = 0; w < model.walls.size(); ++w) {
    const auto& wall = model.walls[w];
    const auto points = lattice_points_inside(wall.shape, dim, d0, layers * d0);
    if (points.empty())
      throw SceneError("wall '" + wall.name + "' " + wall.shape.describe() +
                           " holds no particle: it is thinner than d0 = " + format_length(d0),
                       wall.where, "d0");
    MovingWall moving;
    moving.wall_index = w;
    moving.motion = wall.motion;
    const auto kind = wall.moving() ? ParticleKind::MovingWall : ParticleKind::FixedWall;
    for (const auto& x : points) {
      if (!occupied.insert(lattice_key(x, d0)).second) continue;
      const Vec3 n = wall.shape.normal(x, dim, 0.25 * d0);
      const double depth = -wall.shape.signed_distance(x, dim);
      if (wall.moving()) {
        moving.particles.push_back(static_cast<std::uint32_t>(out.particles.size()));
        moving.reference.push_back(x);
      }
      out.particles.add(kind, x, Vec3::Zero(), static_cast<std::int32_t>(w), n, depth);
      out.wall_slip.push_back(wall.slip);
    }
    if (wall.moving()) out.moving_walls.push_back(std::move(moving));
  }
  add_bodies(model, layers, occupied, out);
  return out;
}

}  // namespace washout
