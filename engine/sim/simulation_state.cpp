// A run's state for checkpoints (washout run --restart, docs/reliability.md "Restart"): what the
// next step reads and does not rebuild itself. Rebuilt by the step and therefore not saved: the
// neighbour grid and lists, the free-surface and squeeze-film marks, the predicted velocity,
// the virtual-marker velocities, the PPE matrix and right-hand side, the active boundary, the
// linear solver (dropped after every frame: run_loop.cpp). Constant and rebuilt from the scene:
// kinds, groups, wall distances and slip, the bodies' models, the contact walls and laws.
#include <omp.h>

#include <cstring>
#include <numeric>
#include <stdexcept>

#include "engine/io/checkpoint.hpp"
#include "engine/sim/rigid_body_system.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {
namespace {

const char* const kAxis[3] = {"_x", "_y", "_z"};

void put_components(io::Checkpoint& c, const std::string& name,
                    const std::array<std::vector<double>, 3>& v) {
  for (int a = 0; a < 3; ++a) c.reals[name + kAxis[a]] = v[a];
}

void get_components(const io::Checkpoint& c, const std::string& name, std::size_t size,
                    std::array<std::vector<double>, 3>& v) {
  for (int a = 0; a < 3; ++a) v[a] = c.real(name + kAxis[a], size);
}

template <class T>
std::uint64_t hash_vector(const std::vector<T>& v, std::uint64_t hash) {
  return io::fnv1a(v.data(), v.size() * sizeof(T), hash);
}

}  // namespace

std::uint64_t Simulation::compute_layout_fingerprint() const {
  const Particles& p = particles_;
  const std::uint64_t counts[3] = {static_cast<std::uint64_t>(p.dim), p.fluid_count, p.size()};
  std::uint64_t hash = io::fnv1a(counts, sizeof counts);
  hash = hash_vector(p.kind, hash);
  hash = hash_vector(p.body, hash);
  hash = hash_vector(p.group, hash);
  hash = hash_vector(p.wall_distance, hash);
  for (int a = 0; a < 3; ++a) {
    hash = hash_vector(p.position[a], hash);
    hash = hash_vector(p.normal[a], hash);
  }
  return hash_vector(walls_.slip, hash);
}

void Simulation::save_state(io::Checkpoint& c) const {
  const Particles& p = particles_;
  c.counts["particles"] = static_cast<std::int64_t>(p.size());
  c.counts["fluid_particles"] = static_cast<std::int64_t>(p.fluid_count);
  std::int64_t layout = 0;
  std::memcpy(&layout, &layout_fingerprint_, sizeof layout);
  c.counts["layout"] = layout;
  c.counts["threads"] = omp_get_max_threads();
  c.counts["step"] = step_;
  c.counts["wall_crossings"] = wall_crossings_;
  c.counts["gap_relocations"] = gap_relocations_;
  c.counts["total_ppe_iterations"] = total_ppe_iterations_;
  c.numbers["time"] = time_;
  c.numbers["max_speed"] = max_speed_;  // the next adaptive step depends on it
  c.numbers["wall_seconds"] = last_report_.wall_seconds;
  c.numbers["energy_initial"] = energy_budget_.initial();
  c.numbers["energy_work_bound"] = energy_budget_.work_bound();
  // Fluid retired as it left the domain (the scene rebuilds their kind as fluid); absent when
  // none left, as in checkpoints written before retirement existed.
  if (!retired_.empty()) {
    c.integers["retired_particles"].assign(retired_.begin(), retired_.end());
    c.numbers["first_retirement_time"] = first_retirement_.time;
    c.counts["first_retirement_step"] = first_retirement_.step;
  }
  // The fluid's order in the arrays (reorder_interval): every array below is in it. Absent
  // while the fluid is at the indices it was built at.
  if (fluid_reordered_)
    c.integers["fluid_order"].assign(p.id.begin(), p.id.begin() + p.fluid_count);
  put_components(c, "position", p.position);
  put_components(c, "velocity", p.velocity);
  put_components(c, "normal", p.normal);  // bodies' normals turn with them
  c.reals["pressure"] = p.pressure;       // also the next pressure solve's first guess
  c.reals["density"] = p.density;
  c.bytes["inside_wall"] = inside_wall_;
  c.reals["probe_values"] = probe_values_;
  // Held from one step to the next, absent until the first step that makes them.
  if (!previous_wall_velocity_[0].empty())
    put_components(c, "previous_wall_velocity", previous_wall_velocity_);
  if (!work_.eddy_viscosity.empty()) c.reals["eddy_viscosity"] = work_.eddy_viscosity;
  if (!work_.surface_strain.empty()) c.reals["surface_strain"] = work_.surface_strain;
  std::vector<double>& walls = c.reals["moving_wall_motion"];
  walls.clear();
  for (const auto& wall : moving_walls_)
    for (const Vec3& v : {wall.displacement, wall.velocity})
      walls.insert(walls.end(), {v.x(), v.y(), v.z()});
  const auto& warm = coupling_.warm_start();
  c.counts["coupling_fields"] = static_cast<std::int64_t>(warm.size());
  for (std::size_t k = 0; k < warm.size(); ++k)
    c.reals["coupling_warm_start_" + std::to_string(k)] = warm[k];
  if (bodies_) bodies_->save_state(c);
}

void Simulation::restore_state(const io::Checkpoint& c) {
  Particles& p = particles_;
  const std::size_t n = p.size();
  if (c.count("particles") != static_cast<std::int64_t>(n) ||
      c.count("fluid_particles") != static_cast<std::int64_t>(p.fluid_count))
    throw io::CheckpointError("the checkpoint holds " + std::to_string(c.count("particles")) +
                              " particles (" + std::to_string(c.count("fluid_particles")) +
                              " fluid), this scene builds " + std::to_string(n) + " (" +
                              std::to_string(p.fluid_count) + " fluid)");
  std::uint64_t layout = 0;
  const std::int64_t stored = c.count("layout");
  std::memcpy(&layout, &stored, sizeof layout);
  if (layout != layout_fingerprint_)
    throw io::CheckpointError(
        "the scene builds its particles in other places than the checkpoint's run did (the same "
        "scene text and parameters, so a module it requires or the engine changed since)");
  // The fluid in the order the checkpoint's arrays hold it, before they are read.
  std::vector<std::uint64_t> ids(p.fluid_count);
  if (c.integers.count("fluid_order")) {
    const std::vector<std::int64_t>& saved = c.integer("fluid_order");
    if (saved.size() != ids.size())
      throw io::CheckpointError("the checkpoint's fluid_order does not name every fluid particle");
    for (std::size_t k = 0; k < ids.size(); ++k) {
      if (saved[k] < 0)
        throw io::CheckpointError("the checkpoint's fluid_order holds a negative id");
      ids[k] = static_cast<std::uint64_t>(saved[k]);
    }
  } else {
    std::iota(ids.begin(), ids.end(), std::uint64_t{0});
  }
  try {
    apply_fluid_order(order_of_ids(p, ids));
  } catch (const std::invalid_argument& e) {
    throw io::CheckpointError(std::string("the checkpoint's fluid_order: ") + e.what());
  }
  step_ = static_cast<long>(c.count("step"));
  wall_crossings_ = static_cast<long>(c.count("wall_crossings"));
  gap_relocations_ = static_cast<long>(c.count("gap_relocations"));
  total_ppe_iterations_ = static_cast<long>(c.count("total_ppe_iterations"));
  time_ = c.number("time");
  max_speed_ = c.number("max_speed");
  last_report_ = StepReport{};
  last_report_.step = step_;
  last_report_.time = time_;
  last_report_.wall_seconds = c.number("wall_seconds");
  energy_budget_.resume(c.number("energy_initial"), c.number("energy_work_bound"));
  get_components(c, "position", n, p.position);
  get_components(c, "velocity", n, p.velocity);
  get_components(c, "normal", n, p.normal);
  p.pressure = c.real("pressure", n);
  p.density = c.real("density", p.density.size());
  inside_wall_ = c.byte("inside_wall", p.fluid_count);
  probe_values_ = c.real("probe_values", model_.probes.size());
  if (c.has_real("previous_wall_velocity_x"))
    get_components(c, "previous_wall_velocity", n, previous_wall_velocity_);
  else
    for (auto& v : previous_wall_velocity_) v.clear();
  if (c.has_real("eddy_viscosity"))
    work_.eddy_viscosity = c.real("eddy_viscosity", p.fluid_count);
  else
    work_.eddy_viscosity.clear();
  if (c.has_real("surface_strain"))
    work_.surface_strain = c.real("surface_strain", p.fluid_count);
  else
    work_.surface_strain.clear();
  const std::vector<double>& walls = c.real("moving_wall_motion", 6 * moving_walls_.size());
  for (std::size_t w = 0; w < moving_walls_.size(); ++w) {
    const double* m = walls.data() + 6 * w;
    moving_walls_[w].displacement = Vec3(m[0], m[1], m[2]);
    moving_walls_[w].velocity = Vec3(m[3], m[4], m[5]);
  }
  const std::int64_t fields = c.count("coupling_fields");
  if (fields < 0 || fields > 6 * static_cast<std::int64_t>(bodies_ ? bodies_->size() : 0))
    throw io::CheckpointError("the checkpoint has " + std::to_string(fields) +
                              " body response fields, more than this scene's bodies have");
  std::vector<std::vector<double>> warm(static_cast<std::size_t>(fields));
  for (std::size_t k = 0; k < warm.size(); ++k) {
    warm[k] = c.real("coupling_warm_start_" + std::to_string(k));
    if (!warm[k].empty() && warm[k].size() != p.fluid_count)
      throw io::CheckpointError("the checkpoint's coupling_warm_start_" + std::to_string(k) +
                                " does not have one value per fluid particle");
  }
  coupling_.set_warm_start(std::move(warm));
  retired_.clear();
  if (c.integers.count("retired_particles")) {
    for (std::int64_t i : c.integer("retired_particles")) {
      if (i < 0 || i >= static_cast<std::int64_t>(p.fluid_count))
        throw io::CheckpointError("the checkpoint retires particle " + std::to_string(i) +
                                  ", not a fluid particle of this scene");
      p.kind[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(ParticleKind::Retired);
      retired_.push_back(static_cast<std::uint32_t>(i));
    }
    first_retirement_ = {c.number("first_retirement_time"),
                         static_cast<long>(c.count("first_retirement_step"))};
  }
  if (bodies_) bodies_->restore_state(c);
}

}  // namespace washout
