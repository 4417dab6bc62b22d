// Corrections after the step, a stage of their own (Stage::push_out), apart from the guards
// that only check (Simulation::check_health): fluid found inside a wall or a body is put back
// d0/2 outside it (push_out.hpp), and fluid caught between two solids, out of one and into the
// other as a gap closes, is moved to the nearest free place in the fluid (free_spot.hpp).
#include <algorithm>
#include <limits>
#include <optional>
#include <sstream>

#include "engine/core/fluid_interpolation.hpp"
#include "engine/sim/free_spot.hpp"
#include "engine/sim/push_out.hpp"
#include "engine/sim/rigid_body_system.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {
namespace {

double squared_separation(const SphContext& ctx, const Vec3& a, const Vec3& b) {
  double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  if (ctx.periodic.any()) ctx.periodic.minimum_image(d);
  return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

constexpr double kHoleRadius = 0.5;  // [d0]: a particle closer than this is on top of another

}  // namespace

// The particles caught this step are skipped where the grid lists them: those still to move
// sit inside a solid, and those already moved are no longer where the grid (built at the start
// of the step) has them. The moved ones count at their new places, from relocated_: without
// them, the water under a landing girder (five particles) was put into one spot behind it at
// twice the water's density, and the pressure there alternated in sign each step, growing
// until a particle ran away (2D wash-out, 0.30 m column, d0 = 0.01 m, t = 1.41 s).
template <class Visit>
void Simulation::for_each_settled_particle_near(const Vec3& y, std::size_t i, bool fluid_only,
                                                Visit&& visit) const {
  const double point[3] = {y[0], y[1], y[2]};
  const auto fluid = static_cast<std::uint32_t>(particles_.fluid_count);
  const auto limit = fluid_only ? fluid : static_cast<std::uint32_t>(particles_.size());
  grid_.for_each_candidate_below(point, limit, [&](std::uint32_t j) {
    if (j == i || (j < fluid && trapped_[j])) return;
    visit(particles_.x(j));
  });
  for (const std::uint32_t j : relocated_) visit(particles_.x(j));
}

bool Simulation::crowded(const Vec3& y, std::size_t i, bool fluid_only) const {
  const double limit2 = kHoleRadius * kHoleRadius * ctx_.d0 * ctx_.d0;
  bool near = false;
  for_each_settled_particle_near(y, i, fluid_only, [&](const Vec3& x) {
    near = near || squared_separation(ctx_, y, x) < limit2;
  });
  return near;
}

void Simulation::push_out_of_solids(StepReport& report) {
  const std::size_t n = particles_.fluid_count;
  const int dim = particles_.dim;
  // Fluid inside a wall: only particles that see a boundary particle can be there.
  std::size_t inside = 0, new_crossings = 0, first_crossing = n;
  trapped_.assign(n, 0);
#pragma omp parallel for reduction(+ : inside, new_crossings) reduction(min : first_crossing) \
    schedule(dynamic, 512)
  for (std::size_t i = 0; i < n; ++i) {
    bool sees_wall = false;
    for (std::uint64_t k = neighbors_.offset[i]; k < neighbors_.offset[i + 1] && !sees_wall; ++k)
      sees_wall = neighbors_.index[k] >= n;
    bool in_wall = false;
    if (sees_wall) {
      // A particle found inside a wall or a body is put back d0/2 outside it (push_out.hpp).
      Vec3 x = particles_.x(i), u = particles_.u(i);
      const double clearance = 0.5 * ctx_.d0;
      for (std::size_t w = 0; w < model_.walls.size() && !in_wall; ++w) {
        const MovingWall* motion = motion_of_wall(w);
        const Vec3 shift = motion ? motion->displacement : Vec3::Zero();
        const Vec3 wall_velocity = motion ? motion->velocity : Vec3::Zero();
        const Shape& shape = model_.walls[w].shape;
        const double distance = shape.signed_distance(x - shift, dim);
        in_wall = distance < 0.0;
        if (in_wall)
          push_out_of_solid(x, u, distance, shape.normal(x - shift, dim, 1e-3 * clearance),
                            clearance, [&](const Vec3&) { return wall_velocity; });
      }
      // Inside a body: test each body it sees once (neighbours of one body come in a row).
      std::int32_t tested = -1;
      for (std::uint64_t k = neighbors_.offset[i];
           k < neighbors_.offset[i + 1] && bodies_ && !in_wall; ++k) {
        const std::int32_t b = particles_.body[neighbors_.index[k]];
        if (b < 0 || b == tested) continue;
        tested = b;
        in_wall = bodies_->push_out(static_cast<std::size_t>(b), x, u, clearance);
      }
      if (in_wall) {
        for (int a = 0; a < dim; ++a) {
          particles_.position[a][i] = x[a];
          particles_.velocity[a][i] = u[a];
        }
        // Out of one solid and into another: caught in a closing gap.
        trapped_[i] = distance_to_solids(x) < 0.0;
      }
    }
    if (in_wall) {
      ++inside;
      if (!inside_wall_[i]) ++new_crossings, first_crossing = std::min(first_crossing, i);
    }
    inside_wall_[i] = in_wall;
  }
  report.particles_in_walls = inside;
  wall_crossings_ += static_cast<long>(new_crossings);
  check_wall_crossings(new_crossings, first_crossing);
  relocated_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (trapped_[i]) move_to_free_place(i, /*nearby_first=*/false);
  // Put back onto another particle: several particles pushed out through the same stretch of
  // a face (under the descending front edge of a rotating girder) land on the same line d0/2
  // outside it, some closer than a fifth of a spacing to each other, and the pressure that
  // pulls them apart alternates in sign each step. Such a particle moves on to a free place,
  // one next to it first (searched as widely as a closing gap's way out, particles put back out
  // of a wall's foot under deep water were carried up to the free surface; free_spot.hpp).
  for (std::size_t i = 0; i < n; ++i)
    if (inside_wall_[i] && !trapped_[i] && crowded(particles_.x(i), i, /*fluid_only=*/true)) {
      trapped_[i] = 1;
      move_to_free_place(i, /*nearby_first=*/true);
    }
}

// The crossing guard (docs/stability.md): a particle or two may slip into a solid in a step
// (a gate's closing gap) and is put back; a whole front of them means the flow or a wall's
// motion outran the step, and pushing them all out would hide it.
void Simulation::check_wall_crossings(std::size_t new_crossings, std::size_t first) const {
  const double limit = model_.params.wall_crossing_limit;
  const std::size_t n = particles_.fluid_count;
  if (!(limit > 0) || first >= n) return;
  const double allowed = std::max(10.0, limit * static_cast<double>(n));
  if (static_cast<double>(new_crossings) <= allowed) return;
  std::ostringstream m;
  m << "wall crossings: " << new_crossings
    << " fluid particles entered a wall or a body in one step, more than wall_crossing_limit = "
    << limit << " of the " << n << " fluid particles (at least 10) allows; the first, particle "
    << first << ", was put back at (" << particles_.position[0][first] << ", "
    << particles_.position[1][first];
  if (particles_.dim == 3) m << ", " << particles_.position[2][first];
  m << ") m";
  throw UnstableError(m.str());
}

double Simulation::distance_to_solids(const Vec3& x) const {
  const int dim = particles_.dim;
  double distance = std::numeric_limits<double>::max();
  for (std::size_t w = 0; w < model_.walls.size(); ++w) {
    const MovingWall* motion = motion_of_wall(w);
    const Vec3 shift = motion ? motion->displacement : Vec3::Zero();
    distance = std::min(distance, model_.walls[w].shape.signed_distance(x - shift, dim));
  }
  for (std::size_t b = 0; bodies_ && b < bodies_->size(); ++b)
    distance = std::min(distance, bodies_->signed_distance(b, x));
  return distance;
}

void Simulation::move_to_free_place(std::size_t i, bool nearby_first) {
  const int dim = particles_.dim;
  const double d0 = ctx_.d0;
  const double r2max = 4.0 * ctx_.h * ctx_.h;
  // A free place must also have fluid within the kernel support: the far side of a wall (as
  // thick as the support) is clear of solids too, but out of the fluid's reach.
  auto clear_of_solids = [&](const Vec3& y) {
    if (!inside_domain(y) || distance_to_solids(y) < 0.5 * d0) return false;
    const double point[3] = {y[0], y[1], y[2]};
    int wet = 0;
    accumulate_fluid_at(ctx_, grid_, particles_, point,
                        [&](std::uint32_t f, double) { wet += f != i; });
    return wet >= 3;
  };
  // A hole in the fluid: no particle within d0/2 of y.
  auto clear_of_fluid = [&](const Vec3& y) {
    return clear_of_solids(y) && !crowded(y, i, /*fluid_only=*/false);
  };
  // Best, a hole with room for it: the kernel-weighted volume of the fluid and the walls there,
  // its own W(0) included, at most that of a full lattice (by the free surface, as a rule), so
  // that it arrives at no more than the water's density. Next to the gap the fluid is usually
  // packed, so next settle for any hole, and last for any place clear of the solids (the order
  // and the reach: find_free_place, free_spot.hpp).
  const double room = ctx_.full_support_density / ctx_.rho0 - ctx_.volume * ctx_.kernel.value(0.0);
  auto with_room = [&](const Vec3& y) {
    if (!clear_of_fluid(y)) return false;
    double occupied = 0.0;
    for_each_settled_particle_near(y, i, /*fluid_only=*/false, [&](const Vec3& x) {
      const double r2 = squared_separation(ctx_, y, x);
      if (r2 < r2max) occupied += ctx_.volume * ctx_.kernel.value(std::sqrt(r2));
    });
    return occupied <= room;
  };
  const std::optional<Vec3> spot = find_free_place(
      particles_.x(i), dim, d0, {with_room, clear_of_fluid, clear_of_solids}, nearby_first);
  if (!spot) return;  // left where it is, still counted as inside a wall
  // It takes the velocity of the fluid around its new place (kernel-weighted).
  const double point[3] = {spot->x(), spot->y(), spot->z()};
  Vec3 sum = Vec3::Zero();
  double weight = 0.0;
  accumulate_fluid_at(ctx_, grid_, particles_, point, [&](std::uint32_t f, double w) {
    if (f == i || trapped_[f]) return;
    sum += w * particles_.u(f);
    weight += w;
  });
  const Vec3 u = weight > 0.0 ? Vec3(sum / weight) : Vec3::Zero();
  for (int a = 0; a < dim; ++a) {
    particles_.position[a][i] = (*spot)[a];
    particles_.velocity[a][i] = u[a];
  }
  relocated_.push_back(static_cast<std::uint32_t>(i));
  ++gap_relocations_;
}

}  // namespace washout
