#include "engine/contact/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <variant>

#include "engine/contact/contact_stiffness.hpp"

namespace washout::contact {
namespace {

using rigid::BodyModel;
using rigid::BodyState;
using rigid::MotionKind;

bool is_dynamic(const BodyModel& model) { return model.motion == MotionKind::kDynamic; }

// 1/m_eff of a unit impulse along n at offset r from X: 1/M + (r x n) . I^-1 (r x n).
// Summed over contacts times their stiffness, this is the trace of the body's contact
// stiffness over its mass matrix, which bounds its largest eigenvalue whatever the number and
// placement of the touching particles: the bound the contacts between bodies add (a pair
// couples two bodies' coordinates). The walls' contacts take the tighter ContactStiffness.
[[gnu::always_inline]] inline double inverse_effective_mass(double inverse_mass,
                                                            const Eigen::Matrix3d& inertia_inverse,
                                                            const Vec3& r, const Vec3& n) {
  const Vec3 arm = r.cross(n);
  return inverse_mass + arm.dot(inertia_inverse * arm);
}

auto spring_key(const PairSpring& s) {
  return std::tie(s.body_a, s.particle_a, s.body_b, s.particle_b);
}

// The near-wall list's skin beyond the reach, in contact radii: a body at rest on a wall
// builds its lists once; one moving a contact radius per fluid step, about once a step.
constexpr double kNearListMargin = 1.0;

// The signed distance grows by at most the distance moved (1-Lipschitz), so a particle no
// further from the body's centre than this radius is at least `margin` from the wall, given
// the centre's distance to it; squared, and negative where no particle qualifies. The 1e-12 m
// covers the rounding of distances of order metres.
double clear_radius2(double centre_distance, double contact_radius, double margin) {
  const double clear = centre_distance - contact_radius - margin - 1e-12;
  return clear > 0.0 ? clear * clear : -1.0;
}

// How far any particle of the body has moved since the list was built, bounded by the
// centre's displacement and the rotation's chord 2 sin(theta/2) |r0| <= 2 |q_v| R.
bool near_list_holds(const NearWallList& near, const BodyModel& model, const BodyState& state,
                     double reach) {
  if (near.skin < 0.0) return false;
  const Eigen::Quaterniond turn = state.orientation * near.orientation.conjugate();
  const double moved =
      (state.position - near.position).norm() + 2.0 * turn.vec().norm() * model.bounding_radius;
  return moved + reach + 1e-12 < near.skin;
}

// Lists the particles within `skin` of the wall; every other particle is separated from it,
// so its tangential spring is reset here, as the sub-steps would.
template <class Shape>
void build_near_list(const Shape& shape, const BodyModel& model, const BodyState& state,
                     const rigid::Vec3Array& x, double centre_distance, double skin,
                     rigid::Vec3Array& spring, std::size_t first, NearWallList& near) {
  const double r = model.contact_radius;
  const double clear2 = clear_radius2(centre_distance, r, skin);
  near.particle.clear();
  near.part_mask.clear();
  Vec3 normal;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 xi(x.x[i], x.y[i], x.z[i]);
    if ((xi - state.position).squaredNorm() > clear2 && shape.distance(xi, normal) - r < skin) {
      near.particle.push_back(static_cast<std::int32_t>(i));
      // While the list holds, no particle has moved as far as `skin` (near_list_holds).
      if constexpr (std::is_same_v<Shape, UnionWall>)
        near.part_mask.push_back(shape.parts_within(xi, skin));
      continue;
    }
    spring.x[first + i] = spring.y[first + i] = spring.z[first + i] = 0.0;
  }
  near.position = state.position;
  near.orientation = state.orientation;
  near.skin = skin;
}

void detect_wall_contacts(std::span<const BodyModel> models, std::span<const BodyState> states,
                          const ContactScene& scene, std::span<const double> reach,
                          ContactWorkspace& ws) {
  const int walls = ws.wall_count;
  const double reference = scene.settings.hertz_reference_overlap;
  for (int b = 0; b < ws.body_count; ++b) {
    const BodyModel& model = models[b];
    if (!is_dynamic(model)) continue;
    const BodyState& state = states[b];
    const double r = model.contact_radius;
    const Eigen::Matrix3d inertia_inverse = rigid::world_inertia_inverse(model, state.orientation);
    const double inverse_mass = 1.0 / model.mass;
    const rigid::Vec3Array& x = ws.position[b];
    const std::size_t n = x.size();
    BodyContactSummary& summary = ws.summary[b];
    ContactStiffness stiffness;  // of the near wall contacts, all walls
    for (int w = 0; w < walls; ++w) {
      const int slot = b * walls + w;
      rigid::Vec3Array& spring = ws.wall_spring[b];
      const std::size_t first = static_cast<std::size_t>(w) * n;
      // The signed distance grows by at most the distance moved, so the whole body is out of
      // reach when its bounding sphere is.
      const double centre_distance = ws.wall_centre_distance[slot];
      if (centre_distance - model.bounding_radius >= reach[b]) {
        if (ws.wall_spring_used[slot]) {
          std::fill_n(spring.x.begin() + first, n, 0.0);
          std::fill_n(spring.y.begin() + first, n, 0.0);
          std::fill_n(spring.z.begin() + first, n, 0.0);
          ws.wall_spring_used[slot] = 0;
        }
        continue;
      }
      const PairLaw& law = ws.wall_law[slot];
      NearWallList& near = ws.near_wall[slot];
      int touching = 0;
      std::visit(
          [&](const auto& shape) {
            Vec3 normal;
            if (!near_list_holds(near, model, state, reach[b]))
              build_near_list(shape, model, state, x, centre_distance,
                              reach[b] + kNearListMargin * r, spring, first, near);
            // By the same bound per particle: one within the clear radius is out of reach,
            // without its distance to the wall (a girder spanning the flume is always near
            // both side walls, but only its ends are).
            const double clear2 = clear_radius2(centre_distance, r, reach[b]);
            for (std::size_t l = 0; l < near.particle.size(); ++l) {
              const std::int32_t i = near.particle[l];
              const Vec3 xi(x.x[i], x.y[i], x.z[i]);
              if ((xi - state.position).squaredNorm() <= clear2) {
                spring.x[first + i] = spring.y[first + i] = spring.z[first + i] = 0.0;
                continue;
              }
              double distance;
              if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, UnionWall>)
                distance = shape.distance(xi, normal, near.part_mask[l]);
              else
                distance = shape.distance(xi, normal);
              const double gap = distance - r;
              const double overlap = -gap;
              if (overlap <= 0.0) {  // separated: the pair's tangential spring is reset
                spring.x[first + i] = spring.y[first + i] = spring.z[first + i] = 0.0;
              }
              if (gap >= reach[b]) continue;
              if (model.dim == 2) {
                normal.z() = 0.0;
                normal.normalize();
              }
              ws.wall_candidates.push_back({b, w, i, overlap, normal});
              if (overlap > 0.0) ++touching;
              stiffness.add(step_stiffnesses(law, overlap, reference * r), normal,
                            xi - state.position);
              ++summary.near;
            }
          },
          scene.walls[w].shape);
      ws.wall_touching[slot] = touching;
      summary.touching += touching;
      if (touching > 0) ws.wall_spring_used[slot] = 1;
    }
    summary.frequency2 += stiffness.largest_frequency2(inverse_mass, inertia_inverse);
  }
}

// Bodies that may meet another body before the next detection (bounding spheres).
struct BodyMeeting {
  bool any = false;
  double cutoff = 0.0;  // the particle pairs' search radius
  int dim = 3;
};
BodyMeeting mark_involved_bodies(std::span<const BodyModel> models,
                                 std::span<const BodyState> states, std::span<const double> reach,
                                 ContactWorkspace& ws) {
  const int bodies = ws.body_count;
  ws.involved.assign(bodies, 0);
  BodyMeeting meeting;
  for (int a = 0; a < bodies; ++a) {
    for (int b = a + 1; b < bodies; ++b) {
      if (!is_dynamic(models[a]) && !is_dynamic(models[b])) continue;
      const double gap = (states[a].position - states[b].position).norm() -
                         models[a].bounding_radius - models[b].bounding_radius;
      if (gap >= reach[a] + reach[b]) continue;
      ws.involved[a] = ws.involved[b] = 1;
      meeting.any = true;
      meeting.cutoff = std::max(meeting.cutoff, models[a].contact_radius +
                                                    models[b].contact_radius + reach[a] + reach[b]);
      meeting.dim = models[a].dim;
    }
  }
  return meeting;
}

void detect_body_contacts(std::span<const BodyModel> models, std::span<const BodyState> states,
                          const ContactScene& scene, std::span<const double> reach,
                          const BodyMeeting& meeting, ContactWorkspace& ws) {
  const int bodies = ws.body_count;
  const std::vector<std::uint8_t>& involved = ws.involved;
  if (!meeting.any) return;
  const double cutoff = meeting.cutoff;
  const int dim = meeting.dim;

  ws.gathered_position.clear();
  ws.gathered_body.clear();
  ws.gathered_particle.clear();
  for (int b = 0; b < bodies; ++b) {
    if (!involved[b]) continue;
    const rigid::Vec3Array& x = ws.position[b];
    for (std::size_t i = 0; i < x.size(); ++i) {
      ws.gathered_position.push_back(x[i]);
      ws.gathered_body.push_back(b);
      ws.gathered_particle.push_back(static_cast<std::int32_t>(i));
    }
  }
  ws.grid.find_pairs(ws.gathered_position, ws.gathered_body, cutoff, dim, ws.pairs);

  const double reference = scene.settings.hertz_reference_overlap;
  std::vector<Eigen::Matrix3d>& inertia_inverse = ws.inertia_inverse;
  inertia_inverse.resize(bodies);
  for (int b = 0; b < bodies; ++b)
    if (involved[b])
      inertia_inverse[b] = rigid::world_inertia_inverse(models[b], states[b].orientation);
  for (const ParticlePair& p : ws.pairs) {
    int ga = p.i, gb = p.j;
    if (ws.gathered_body[ga] > ws.gathered_body[gb]) std::swap(ga, gb);
    const int a = ws.gathered_body[ga], b = ws.gathered_body[gb];
    const BodyModel& ma = models[a];
    const BodyModel& mb = models[b];
    if (!is_dynamic(ma) && !is_dynamic(mb)) continue;
    const Vec3 xa = ws.gathered_position[ga], xb = ws.gathered_position[gb];
    Vec3 d = xa - xb;
    if (dim == 2) d.z() = 0.0;
    const double distance = d.norm();
    const double gap = distance - ma.contact_radius - mb.contact_radius;
    if (gap >= reach[a] + reach[b] || !(distance > 0.0)) continue;
    const Vec3 normal = d / distance;
    const double overlap = -gap;
    ws.pair_candidates.push_back(
        {a, ws.gathered_particle[ga], b, ws.gathered_particle[gb], overlap, normal});
    if (overlap > 0.0) {
      ++ws.pair_touching[a * bodies + b];
      ++ws.summary[a].touching;
      ++ws.summary[b].touching;
    }
    // Both bodies feel this contact: its stiffness over the pair's relative inverse mass.
    double inverse_mass = 0.0;
    if (is_dynamic(ma))
      inverse_mass += inverse_effective_mass(1.0 / ma.mass, inertia_inverse[a],
                                             xa - states[a].position, normal);
    if (is_dynamic(mb))
      inverse_mass += inverse_effective_mass(1.0 / mb.mass, inertia_inverse[b],
                                             xb - states[b].position, normal);
    const double f2 =
        step_stiffness(ws.pair_law[a * bodies + b], overlap, reference * ma.contact_radius) *
        inverse_mass;
    ws.summary[a].frequency2 += f2;
    ws.summary[b].frequency2 += f2;
    ++ws.summary[a].near;
    ++ws.summary[b].near;
  }
}

}  // namespace

void ContactWorkspace::prepare(std::span<const BodyModel> models, const ContactScene& scene) {
  const int bodies = static_cast<int>(models.size());
  const int walls = static_cast<int>(scene.walls.size());
  if (bodies == body_count && walls == wall_count) return;  // laws and history already there
  body_count = bodies;
  wall_count = walls;
  const MaterialTable& table = scene.materials;
  wall_law.resize(static_cast<std::size_t>(bodies) * walls);
  pair_law.resize(static_cast<std::size_t>(bodies) * bodies);
  for (int b = 0; b < bodies; ++b) {
    const int mb = models[b].material;
    for (int w = 0; w < walls; ++w) {
      const int mw = scene.walls[w].material;
      wall_law[b * walls + w] =
          make_pair_law(scene.settings, models[b].contact_radius, table.material(mb),
                        table.material(mw), table.friction(mb, mw), table.restitution(mb, mw));
    }
    for (int c = 0; c < bodies; ++c) {
      const int mc = models[c].material;
      // Particles of one radius in practice; with two, the smaller sets the stiffness.
      const double radius = std::min(models[b].contact_radius, models[c].contact_radius);
      pair_law[b * bodies + c] =
          make_pair_law(scene.settings, radius, table.material(mb), table.material(mc),
                        table.friction(mb, mc), table.restitution(mb, mc));
    }
  }
  position.assign(bodies, {});
  velocity.assign(bodies, {});
  wall_spring.assign(bodies, {});
  for (int b = 0; b < bodies; ++b) {
    wall_spring[b].resize(models[b].contact_offset.size() * static_cast<std::size_t>(walls));
    std::fill(wall_spring[b].x.begin(), wall_spring[b].x.end(), 0.0);
    std::fill(wall_spring[b].y.begin(), wall_spring[b].y.end(), 0.0);
    std::fill(wall_spring[b].z.begin(), wall_spring[b].z.end(), 0.0);
  }
  wall_spring_used.assign(static_cast<std::size_t>(bodies) * walls, 0);
  near_wall.assign(static_cast<std::size_t>(bodies) * walls, {});
  pair_spring.clear();
  next_pair_spring.clear();
}

void detect_contacts(std::span<const BodyModel> models, std::span<const BodyState> states,
                     const ContactScene& scene, std::span<const double> reach,
                     ContactWorkspace& ws) {
  if (ws.body_count != static_cast<int>(models.size()) ||
      ws.wall_count != static_cast<int>(scene.walls.size()))
    throw std::logic_error("detect_contacts: ContactWorkspace::prepare was not called");
  const int bodies = ws.body_count;
  ws.wall_candidates.clear();
  ws.pair_candidates.clear();
  ws.wall_touching.assign(static_cast<std::size_t>(bodies) * ws.wall_count, 0);
  ws.pair_touching.assign(static_cast<std::size_t>(bodies) * bodies, 0);
  ws.summary.assign(bodies, {});
  const BodyMeeting meeting = mark_involved_bodies(models, states, reach, ws);
  ws.wall_centre_distance.resize(static_cast<std::size_t>(bodies) * ws.wall_count);
  for (int b = 0; b < bodies; ++b) {
    const BodyModel& model = models[b];
    const BodyState& state = states[b];
    const rigid::Vec3Array& offset = model.contact_offset;
    // Every particle where all are read: a body that may meet another, or a wall whose near list
    // is rebuilt; otherwise (a body at rest on its pier: 136 of 644 particles) those of the near
    // lists of the walls in reach, which are all that detection and the loads read. A fixed or
    // prescribed body meets walls in no way, so it needs none unless it meets a body.
    bool every = ws.involved[b] != 0;
    const auto in_reach = [&](int slot) {
      return ws.wall_centre_distance[slot] - model.bounding_radius < reach[b];
    };
    for (int w = 0; w < ws.wall_count && is_dynamic(model); ++w) {
      const int slot = b * ws.wall_count + w;
      ws.wall_centre_distance[slot] = signed_distance(scene.walls[w].shape, state.position);
      if (in_reach(slot) && !near_list_holds(ws.near_wall[slot], model, state, reach[b]))
        every = true;
    }
    if (every) {
      rigid::particle_positions(state, offset, ws.position[b]);
      rigid::particle_velocities(state, offset, ws.velocity[b]);
      continue;
    }
    ws.position[b].resize(offset.size());
    ws.velocity[b].resize(offset.size());
    for (int w = 0; w < ws.wall_count && is_dynamic(model); ++w) {
      const int slot = b * ws.wall_count + w;
      if (in_reach(slot))
        rigid::particle_kinematics_of(state, offset, ws.near_wall[slot].particle, ws.position[b],
                                      ws.velocity[b]);
    }
  }
  detect_wall_contacts(models, states, scene, reach, ws);
  detect_body_contacts(models, states, scene, reach, meeting, ws);
}

void contact_loads(std::span<const BodyModel> models, std::span<const BodyState> states,
                   const ContactScene& scene, double h, ContactWorkspace& ws,
                   std::vector<rigid::BodyLoad>& loads) {
  const int bodies = ws.body_count;
  const int walls = ws.wall_count;
  const bool shared = scene.settings.damping_mass == DampingMass::kShared;
  loads.assign(bodies, {});

  // Normal speeds, and the contacts that act during this step (touching now, or starting
  // within it) per body and partner: they share the body's mass for the dashpot.
  auto wall_rate = [&](const WallCandidate& c) {
    return -ws.velocity[c.body][c.particle].dot(c.normal);
  };
  auto pair_relative = [&](const PairCandidate& c) {
    return Vec3(ws.velocity[c.body_a][c.particle_a] - ws.velocity[c.body_b][c.particle_b]);
  };
  std::fill(ws.wall_touching.begin(), ws.wall_touching.end(), 0);
  std::fill(ws.pair_touching.begin(), ws.pair_touching.end(), 0);
  for (const WallCandidate& c : ws.wall_candidates)
    if (touches_during_step(c.overlap, wall_rate(c), h))
      ++ws.wall_touching[c.body * walls + c.wall];
  for (const PairCandidate& c : ws.pair_candidates)
    if (touches_during_step(c.overlap, -pair_relative(c).dot(c.normal), h))
      ++ws.pair_touching[c.body_a * bodies + c.body_b];

  // The candidates come body by body and wall by wall: one dashpot coefficient per run of them.
  int dashpot_slot = -1;
  double dashpot = 0.0;
  for (const WallCandidate& c : ws.wall_candidates) {
    const double rate = wall_rate(c);
    if (!touches_during_step(c.overlap, rate, h)) continue;
    const BodyModel& model = models[c.body];
    const int slot = c.body * walls + c.wall;
    const rigid::Vec3Array& x = ws.position[c.body];
    const Vec3 ui = ws.velocity[c.body][c.particle];
    ContactKinematics k;
    k.overlap = c.overlap;
    k.overlap_rate = rate;
    k.normal = c.normal;
    k.tangential_velocity = ui + rate * c.normal;
    k.damping_mass = shared ? model.mass / ws.wall_touching[slot] : model.mass;
    if (slot != dashpot_slot) {
      dashpot_slot = slot;
      dashpot = dashpot_coefficient(ws.wall_law[slot], k.damping_mass);
    }
    rigid::Vec3Array& springs = ws.wall_spring[c.body];
    const std::size_t s = static_cast<std::size_t>(c.wall) * x.size() + c.particle;
    Vec3 spring = springs[s];
    const Vec3 force = spring_dashpot_force(ws.wall_law[slot], k, dashpot, h, spring);
    springs.set(s, spring);
    ws.wall_spring_used[slot] = 1;
    // Applied at the contact point, the middle of the overlap (METHOD.md's r_i x F_c,i with
    // r_i taken to the contact rather than the particle centre: same for the normal force,
    // the friction torque gets the arm of the real surface).
    const Vec3 point = x[c.particle] - (model.contact_radius - 0.5 * c.overlap) * c.normal;
    rigid::BodyLoad& load = loads[c.body];
    load.force += force;
    load.torque += (point - states[c.body].position).cross(force);
  }

  ws.next_pair_spring.clear();
  for (const PairCandidate& c : ws.pair_candidates) {
    const Vec3 relative = pair_relative(c);
    const double rate = -relative.dot(c.normal);
    if (!touches_during_step(c.overlap, rate, h)) continue;
    const BodyModel& ma = models[c.body_a];
    const BodyModel& mb = models[c.body_b];
    const Vec3 xb = ws.position[c.body_b][c.particle_b];
    // Reduced mass of the pair; a fixed or prescribed body counts as infinitely heavy.
    double reduced = is_dynamic(ma) && is_dynamic(mb) ? ma.mass * mb.mass / (ma.mass + mb.mass)
                                                      : (is_dynamic(ma) ? ma.mass : mb.mass);
    if (shared) reduced /= ws.pair_touching[c.body_a * bodies + c.body_b];
    ContactKinematics k;
    k.overlap = c.overlap;
    k.overlap_rate = rate;
    k.normal = c.normal;
    k.tangential_velocity = relative + rate * c.normal;
    k.damping_mass = reduced;
    PairSpring key{c.body_a, c.particle_a, c.body_b, c.particle_b, Vec3::Zero()};
    auto it = std::lower_bound(
        ws.pair_spring.begin(), ws.pair_spring.end(), key,
        [](const PairSpring& l, const PairSpring& r) { return spring_key(l) < spring_key(r); });
    if (it != ws.pair_spring.end() && spring_key(*it) == spring_key(key)) key.spring = it->spring;
    const Vec3 force =
        spring_dashpot_force(ws.pair_law[c.body_a * bodies + c.body_b], k, h, key.spring);
    if (c.overlap + h * rate > 0.0) ws.next_pair_spring.push_back(key);  // still touching
    // Both bodies take the force at one contact point, so that the pair's torques about any
    // point cancel and the total angular momentum is conserved.
    const Vec3 point = xb + (mb.contact_radius - 0.5 * c.overlap) * c.normal;
    loads[c.body_a].force += force;
    loads[c.body_a].torque += (point - states[c.body_a].position).cross(force);
    loads[c.body_b].force -= force;
    loads[c.body_b].torque -= (point - states[c.body_b].position).cross(force);
  }
  std::sort(ws.next_pair_spring.begin(), ws.next_pair_spring.end(),
            [](const PairSpring& l, const PairSpring& r) { return spring_key(l) < spring_key(r); });
  ws.pair_spring.swap(ws.next_pair_spring);

  for (int b = 0; b < bodies; ++b) {
    if (models[b].dim != 2) continue;
    loads[b].force.z() = 0.0;
    loads[b].torque.x() = loads[b].torque.y() = 0.0;
  }
}

}  // namespace washout::contact
