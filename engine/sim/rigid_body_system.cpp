#include "engine/sim/rigid_body_system.hpp"

#include <cmath>
#include <span>
#include <sstream>
#include <stdexcept>

#include "engine/contact/shape_wall.hpp"
#include "engine/io/checkpoint.hpp"
#include "engine/rigid/hydrodynamic_load.hpp"
#include "engine/sim/body_surface_pressure.hpp"
#include "engine/sim/push_out.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {
namespace {

contact::ContactSettings contact_settings(const ContactSpec& spec) {
  contact::ContactSettings s;
  s.law = spec.law == "hertz" ? contact::ContactLaw::kHertz : contact::ContactLaw::kLinear;
  s.damping_mass = spec.damping_mass == "whole_body" ? contact::DampingMass::kWholeBody
                                                     : contact::DampingMass::kShared;
  s.allow_tension = spec.allow_tension;
  s.steps_per_contact = spec.steps_per_contact;
  s.max_substeps = spec.max_substeps;
  return s;
}

// Materials by name ("default" unless the scene defines it: the paper's PLA), the fixed walls
// (moving walls take no part in contact) and the per-pair friction and restitution.
contact::ContactScene make_contact_scene(const Model& model) {
  contact::ContactScene scene;
  scene.settings = contact_settings(model.contact);
  for (const auto& m : model.materials)
    scene.materials.add({m.name, m.young_modulus, m.poisson_ratio, m.restitution});
  if (scene.materials.find("default") < 0) scene.materials.add({"default"});
  auto id = [&](const std::string& name, const SourceLocation& where) {
    const int k = scene.materials.find(name.empty() ? "default" : name);
    if (k < 0)
      throw SceneError("unknown contact material '" + name + "' (define it with washout.material)",
                       where, "material");
    return k;
  };
  for (const auto& f : model.frictions) {
    const int a = id(f.material_a, f.where), b = id(f.material_b, f.where);
    scene.materials.set_friction(a, b, f.friction);
    if (f.restitution >= 0.0) scene.materials.set_restitution(a, b, f.restitution);
  }
  for (const auto& wall : model.walls) {
    const int material = id(wall.material, wall.where);
    if (wall.moving()) continue;
    scene.walls.push_back(
        {wall.name, contact::wall_shape_from(wall.shape, model.params.dim), material});
  }
  return scene;
}

std::string format_vector(const Vec3& v, int dim) {
  std::ostringstream o;
  o << "(" << v.x() << ", " << v.y();
  if (dim == 3) o << ", " << v.z();
  o << ")";
  return o.str();
}

}  // namespace

RigidBodySystem::RigidBodySystem(const Model& model, std::vector<BuiltBody> bodies,
                                 std::vector<std::size_t> first_particle)
    : dim_(model.params.dim), first_(std::move(first_particle)), rest_(model.contact.rest_steps) {
  contact_ = make_contact_scene(model);
  const std::size_t count = bodies.size();
  surface_begin_.push_back(0);
  for (std::size_t b = 0; b < count; ++b) {
    BuiltBody& built = bodies[b];
    const BodySpec& spec = model.bodies[b];
    built.model.material =
        contact_.materials.find(spec.material.empty() ? "default" : spec.material);
    if (built.model.material < 0)
      throw SceneError("unknown contact material '" + spec.material + "' of body '" + spec.name +
                           "' (define it with washout.material)",
                       spec.where, "material");
    rigid::Vec3Array normal;
    for (const Vec3& n : built.normal) normal.push_back(n);
    reference_normal_.push_back(std::move(normal));
    for (const std::int32_t k : built.model.surface_index)
      surface_particles_.push_back(static_cast<std::uint32_t>(first_[b] + k));
    surface_begin_.push_back(surface_particles_.size());
    shapes_.push_back(spec.shape);
    volumes_.push_back(built.solid.volume);
    angles_.emplace_back(dim_ == 2 ? Vec3::UnitZ() : spec.angle_axis);
    angles_.back().update(built.initial.orientation);
    models_.push_back(std::move(built.model));
    states_.push_back(built.initial);
  }
  fluid_loads_.assign(count, {});
  contact_loads_.assign(count, {});
  last_report_.contact_load.assign(count, {});
}

void RigidBodySystem::place_body(std::size_t b, Particles& p) const {
  const rigid::BodyModel& model = models_[b];
  const rigid::BodyState& s = states_[b];
  const Eigen::Matrix3d R = rigid::rotation_matrix(s.orientation);
  const rigid::Vec3Array& r0 = model.offset;
  const rigid::Vec3Array& n0 = reference_normal_[b];
  const std::size_t first = first_[b];
  // METHOD.md Rigid bodies: x_i = X + R r0_i, u_i = T + w x (R r0_i); normals turn with R.
  for (std::size_t k = 0; k < r0.size(); ++k) {
    const Vec3 r = R * r0[k];
    const Vec3 u = s.velocity + s.angular_velocity.cross(r);
    const Vec3 n = R * n0[k];
    const std::size_t i = first + k;
    for (int a = 0; a < dim_; ++a) {
      p.position[a][i] = s.position[a] + r[a];
      p.velocity[a][i] = u[a];
      p.normal[a][i] = n[a];
    }
  }
}

void RigidBodySystem::place_particles(Particles& p) const {
  for (std::size_t b = 0; b < size(); ++b) place_body(b, p);
}

void RigidBodySystem::set_prescribed_velocities(double t, Particles& p) const {
  for (std::size_t b = 0; b < size(); ++b) {
    const rigid::BodyModel& model = models_[b];
    if (model.motion != rigid::MotionKind::kPrescribed) continue;
    const rigid::BodyState next = model.prescribed(t);
    const std::size_t first = first_[b];
    for (std::size_t k = 0; k < model.offset.size(); ++k) {
      const std::size_t i = first + k;
      const Vec3 r = p.x(i) - states_[b].position;
      const Vec3 u = next.velocity + next.angular_velocity.cross(r);
      for (int a = 0; a < dim_; ++a) p.velocity[a][i] = u[a];
    }
  }
}

// Hydrodynamic load, METHOD.md Rigid bodies: F_f = sum -P_i n_i dS_i, M_f = sum r_i x (-P_i n_i
// dS_i), with P_i the pressure on the surface point s_i = x_i + d_i n_i (also the arm r_i) and
// n_i dS_i the particle's share of the surface (body_builder.hpp).
void RigidBodySystem::compute_fluid_loads(const SphContext& ctx, const NeighborGrid& grid,
                                          const Particles& p, const Vec3& gravity) {
  dry_ = no_fluid_near(ctx, p);
  if (!dry_) rest_.wake();  // fluid near: the bodies move again from the pose they slept in
  if (dry_)  // what the search would find: no fluid around any mirror point, a pressure of 0
    surface_pressure_.assign(surface_particles_.size(), 0.0);
  else
    body_surface_pressure(ctx, grid, p, gravity, surface_particles_, surface_pressure_);
  loads_of_surface_pressure(p);
  fluid_loads_ = scratch_loads_;
}

bool RigidBodySystem::no_fluid_near(const SphContext& ctx, const Particles& p) const {
  const FluidBox fluid = fluid_box(p);
  for (std::size_t b = 0; b < size(); ++b)
    if (!beyond_fluid_reach(ctx, p, fluid, first_[b], models_[b].offset.size())) return false;
  return true;
}

void RigidBodySystem::build_linear_load(const SphContext& ctx, const NeighborGrid& grid,
                                        const Particles& p, std::span<const std::int32_t> unknown) {
  build_surface_stencil(ctx, grid, p, surface_particles_, unknown, surface_stencil_);
}

const std::vector<rigid::BodyLoad>& RigidBodySystem::linear_load(const SphContext& ctx,
                                                                 const Particles& p,
                                                                 std::span<const double> rows) {
  stencil_pressure(ctx, surface_stencil_, rows, surface_pressure_);
  loads_of_surface_pressure(p);
  return scratch_loads_;
}

// Hydrodynamic load, METHOD.md Rigid bodies: F_f = sum -P_i n_i dS_i, M_f = sum r_i x (-P_i n_i
// dS_i), with P_i the pressure on the surface point s_i = x_i + d_i n_i (also the arm r_i) and
// n_i dS_i the particle's share of the surface (body_builder.hpp).
void RigidBodySystem::loads_of_surface_pressure(const Particles& p) {
  scratch_loads_.resize(size());
  for (std::size_t b = 0; b < size(); ++b) {
    const std::size_t begin = surface_begin_[b], end = surface_begin_[b + 1];
    const Eigen::Matrix3d R = rigid::rotation_matrix(states_[b].orientation);
    const rigid::Vec3Array& surface_normal = models_[b].surface_normal;
    load_point_.resize(end - begin);
    load_normal_.resize(end - begin);
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t i = surface_particles_[k];
      const Vec3 n_wall(p.normal[0][i], p.normal[1][i], p.normal[2][i]);
      load_point_.set(k - begin, p.x(i) + p.wall_distance[i] * n_wall);
      load_normal_.set(k - begin, R * surface_normal[k - begin]);
    }
    rigid::BodyLoad& load = scratch_loads_[b];
    load = rigid::hydrodynamic_load(
        std::span<const double>(surface_pressure_).subspan(begin, end - begin), load_point_,
        load_normal_, models_[b].surface_area, states_[b].position);
    if (dim_ == 2) {
      load.force.z() = 0.0;
      load.torque.x() = load.torque.y() = 0.0;
    }
  }
}

long RigidBodySystem::advance(double t, double dt, const Vec3& gravity, Particles& p) {
  if (rest_.asleep()) {  // still, balanced and dry: nothing the sub-steps would change
    last_report_.substeps = 0;
    ++asleep_steps_;
    return 0;
  }
  try {
    last_report_ = contact::advance_bodies(models_, states_, fluid_loads_, contact_, workspace_,
                                           gravity, t, dt);
  } catch (const SceneError&) {
    throw;  // a prescribed motion that failed: the scene's fault
  } catch (const std::runtime_error& e) {
    throw UnstableError(std::string("rigid bodies: ") + e.what());
  }
  contact_loads_ = last_report_.contact_load;
  for (std::size_t b = 0; b < size(); ++b) {
    const rigid::BodyState& s = states_[b];
    const bool finite = s.position.allFinite() && s.velocity.allFinite() &&
                        s.angular_velocity.allFinite() && s.orientation.coeffs().allFinite();
    if (!finite)
      throw UnstableError("body '" + name(b) + "' has a non-finite state (fluid load " +
                          format_vector(fluid_loads_[b].force, dim_) + " N, contact load " +
                          format_vector(contact_loads_[b].force, dim_) + " N)");
    angles_[b].update(s.orientation);
    if (models_[b].motion != rigid::MotionKind::kFixed) place_body(b, p);
  }
  if (rest_.observe(models_, states_, fluid_loads_, contact_loads_, gravity, dt, dry_))
    for (std::size_t b = 0; b < size(); ++b)
      if (dynamic(b)) {  // asleep from here: exactly still, and so are its particles
        states_[b].velocity = states_[b].angular_velocity = Vec3::Zero();
        place_body(b, p);
      }
  return last_report_.substeps;
}

void RigidBodySystem::check_overlap(double max_overlap) const {
  if (!(max_overlap > 0)) return;
  // The contacts of the last sub-step's detection: the deepest of each kind.
  const contact::WallCandidate* wall = nullptr;
  for (const auto& c : workspace_.wall_candidates)
    if (!wall || c.overlap > wall->overlap) wall = &c;
  const contact::PairCandidate* pair = nullptr;
  for (const auto& c : workspace_.pair_candidates)
    if (!pair || c.overlap > pair->overlap) pair = &c;
  std::ostringstream m;
  m.precision(4);
  if (wall && wall->overlap > max_overlap && (!pair || wall->overlap >= pair->overlap)) {
    m << "body '" << name(wall->body) << "' overlaps wall '" << contact_.walls[wall->wall].name
      << "' by " << wall->overlap << " m";
  } else if (pair && pair->overlap > max_overlap) {
    m << "bodies '" << name(pair->body_a) << "' and '" << name(pair->body_b) << "' overlap by "
      << pair->overlap << " m";
  } else {
    return;
  }
  m << ", more than contact_overlap_limit allows (" << max_overlap
    << " m): the contact is too soft for the load (raise E) or a body passed into a solid";
  throw UnstableError(m.str());
}

Vec3 RigidBodySystem::reference_point(std::size_t b, const Vec3& x) const {
  const rigid::BodyState& s = states_[b];
  return s.orientation.conjugate() * (x - s.position) + models_[b].centre_of_mass;
}

bool RigidBodySystem::contains(std::size_t b, const Vec3& x) const {
  return signed_distance(b, x) < 0.0;
}

double RigidBodySystem::signed_distance(std::size_t b, const Vec3& x) const {
  return shapes_[b].signed_distance(reference_point(b, x), dim_);
}

Vec3 RigidBodySystem::velocity_at(std::size_t b, const Vec3& x) const {
  const rigid::BodyState& s = states_[b];
  return s.velocity + s.angular_velocity.cross(x - s.position);
}

bool RigidBodySystem::push_out(std::size_t b, Vec3& x, Vec3& u, double clearance) const {
  const rigid::BodyState& s = states_[b];
  const Vec3 reference = reference_point(b, x);
  const double distance = shapes_[b].signed_distance(reference, dim_);
  if (distance >= 0.0) return false;
  const Vec3 normal = s.orientation * shapes_[b].normal(reference, dim_, 1e-3 * clearance);
  push_out_of_solid(x, u, distance, normal, clearance,
                    [&](const Vec3& y) { return velocity_at(b, y); });
  return true;
}

void RigidBodySystem::save_state(io::Checkpoint& c) const {
  const std::size_t count = size();
  auto vectors = [&](const char* name, auto&& of) {
    std::vector<double>& out = c.reals[name];
    out.clear();
    for (std::size_t b = 0; b < count; ++b) {
      const Vec3 v = of(b);
      out.insert(out.end(), {v.x(), v.y(), v.z()});
    }
  };
  vectors("body_position", [&](std::size_t b) { return states_[b].position; });
  vectors("body_velocity", [&](std::size_t b) { return states_[b].velocity; });
  vectors("body_angular_velocity", [&](std::size_t b) { return states_[b].angular_velocity; });
  vectors("body_fluid_force", [&](std::size_t b) { return fluid_loads_[b].force; });
  vectors("body_fluid_torque", [&](std::size_t b) { return fluid_loads_[b].torque; });
  vectors("body_contact_force", [&](std::size_t b) { return contact_loads_[b].force; });
  vectors("body_contact_torque", [&](std::size_t b) { return contact_loads_[b].torque; });
  std::vector<double>& q = c.reals["body_orientation"];
  std::vector<double>& angle = c.reals["body_angle"];
  q.clear();
  angle.clear();
  for (std::size_t b = 0; b < count; ++b) {
    const Eigen::Quaterniond& o = states_[b].orientation;
    q.insert(q.end(), {o.w(), o.x(), o.y(), o.z()});
    angle.insert(angle.end(), {angles_[b].angle(), angles_[b].last_twist()});
  }
  // Contact history: the tangential springs against walls and between bodies.
  const contact::ContactWorkspace& ws = workspace_;
  std::vector<double>&sx = c.reals["contact_wall_spring_x"], &sy = c.reals["contact_wall_spring_y"],
  &sz = c.reals["contact_wall_spring_z"];
  sx.clear(), sy.clear(), sz.clear();
  for (const auto& spring : ws.wall_spring) {
    sx.insert(sx.end(), spring.x.begin(), spring.x.end());
    sy.insert(sy.end(), spring.y.begin(), spring.y.end());
    sz.insert(sz.end(), spring.z.begin(), spring.z.end());
  }
  c.bytes["contact_wall_spring_used"] = ws.wall_spring_used;
  std::vector<std::int64_t>& keys = c.integers["contact_pair_key"];
  std::vector<double>& pair = c.reals["contact_pair_spring"];
  keys.clear();
  pair.clear();
  for (const auto& s : ws.pair_spring) {
    keys.insert(keys.end(), {s.body_a, s.particle_a, s.body_b, s.particle_b});
    pair.insert(pair.end(), {s.spring.x(), s.spring.y(), s.spring.z()});
  }
  c.counts["contact_prepared"] = ws.body_count >= 0;
  c.counts["body_rest_steps"] = rest_.still_steps();
  c.counts["body_asleep_steps"] = asleep_steps_;
}

void RigidBodySystem::restore_state(const io::Checkpoint& c) {
  const std::size_t count = size();
  auto vectors = [&](const char* name, auto&& set) {
    const std::vector<double>& v = c.real(name, 3 * count);
    for (std::size_t b = 0; b < count; ++b) set(b, Vec3(v[3 * b], v[3 * b + 1], v[3 * b + 2]));
  };
  vectors("body_position", [&](std::size_t b, const Vec3& v) { states_[b].position = v; });
  vectors("body_velocity", [&](std::size_t b, const Vec3& v) { states_[b].velocity = v; });
  vectors("body_angular_velocity",
          [&](std::size_t b, const Vec3& v) { states_[b].angular_velocity = v; });
  vectors("body_fluid_force", [&](std::size_t b, const Vec3& v) { fluid_loads_[b].force = v; });
  vectors("body_fluid_torque", [&](std::size_t b, const Vec3& v) { fluid_loads_[b].torque = v; });
  vectors("body_contact_force", [&](std::size_t b, const Vec3& v) { contact_loads_[b].force = v; });
  vectors("body_contact_torque",
          [&](std::size_t b, const Vec3& v) { contact_loads_[b].torque = v; });
  last_report_.contact_load = contact_loads_;
  // Absent from checkpoints written before bodies could sleep: awake.
  rest_.restore(c.counts.count("body_rest_steps") ? int(c.count("body_rest_steps")) : 0);
  asleep_steps_ = c.counts.count("body_asleep_steps") ? long(c.count("body_asleep_steps")) : 0;
  const std::vector<double>& q = c.real("body_orientation", 4 * count);
  const std::vector<double>& angle = c.real("body_angle", 2 * count);
  for (std::size_t b = 0; b < count; ++b) {
    states_[b].orientation = Eigen::Quaterniond(q[4 * b], q[4 * b + 1], q[4 * b + 2], q[4 * b + 3]);
    angles_[b].restore(angle[2 * b], angle[2 * b + 1]);
  }
  contact::ContactWorkspace& ws = workspace_;
  if (c.count("contact_prepared") == 0) return;  // no step yet: no contact history
  ws.prepare(models_, contact_);
  std::size_t springs = 0;
  for (const auto& spring : ws.wall_spring) springs += spring.size();
  const std::vector<double>&sx = c.real("contact_wall_spring_x", springs),
        &sy = c.real("contact_wall_spring_y", springs),
        &sz = c.real("contact_wall_spring_z", springs);
  std::size_t k = 0;
  for (auto& spring : ws.wall_spring)
    for (std::size_t i = 0; i < spring.size(); ++i, ++k) {
      spring.x[i] = sx[k];
      spring.y[i] = sy[k];
      spring.z[i] = sz[k];
    }
  ws.wall_spring_used = c.byte("contact_wall_spring_used", ws.wall_spring_used.size());
  const std::vector<std::int64_t>& keys = c.integer("contact_pair_key");
  if (keys.size() % 4 != 0)
    throw io::CheckpointError("the checkpoint's contact_pair_key is not a list of 4-tuples");
  const std::vector<double>& pair = c.real("contact_pair_spring", keys.size() / 4 * 3);
  ws.pair_spring.clear();
  for (std::size_t s = 0; s < keys.size() / 4; ++s) {
    contact::PairSpring spring;
    spring.body_a = static_cast<std::int32_t>(keys[4 * s]);
    spring.particle_a = static_cast<std::int32_t>(keys[4 * s + 1]);
    spring.body_b = static_cast<std::int32_t>(keys[4 * s + 2]);
    spring.particle_b = static_cast<std::int32_t>(keys[4 * s + 3]);
    const bool valid =
        spring.body_a >= 0 && spring.body_b >= 0 &&
        static_cast<std::size_t>(spring.body_a) < count &&
        static_cast<std::size_t>(spring.body_b) < count && spring.particle_a >= 0 &&
        spring.particle_b >= 0 &&
        static_cast<std::size_t>(spring.particle_a) <
            models_[spring.body_a].contact_offset.size() &&
        static_cast<std::size_t>(spring.particle_b) < models_[spring.body_b].contact_offset.size();
    if (!valid)
      throw io::CheckpointError(
          "the checkpoint's contact springs name particles these bodies do "
          "not have");
    spring.spring = Vec3(pair[3 * s], pair[3 * s + 1], pair[3 * s + 2]);
    ws.pair_spring.push_back(spring);
  }
}

}  // namespace washout
