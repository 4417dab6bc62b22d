#include "engine/sim/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "engine/boundary/squeeze_film.hpp"
#include "engine/boundary/virtual_markers.hpp"
#include "engine/boundary/wall_acceleration.hpp"
#include "engine/core/fluid_interpolation.hpp"
#include "engine/fluid/density_relaxation.hpp"
#include "engine/fluid/isph_stages.hpp"
#include "engine/sim/particle_builder.hpp"
#include "engine/sim/probes.hpp"
#include "engine/sim/rigid_body_system.hpp"

namespace washout {
namespace {

PeriodicBox make_periodic_box(const SimulationParameters& p) {
  PeriodicBox box;
  for (char c : p.periodic) {
    const int a = c - 'x';
    box.periodic[a] = true;
    box.lower[a] = p.domain_min[a];
    box.length[a] = p.domain_max[a] - p.domain_min[a];
    if (!(box.length[a] > 0))
      throw SceneError(std::string("periodic axis ") + c + " needs domain_max > domain_min", "",
                       "domain_max");
  }
  return box;
}

std::string format_point(const Particles& p, std::size_t i) {
  std::ostringstream o;
  o << "(" << p.position[0][i] << ", " << p.position[1][i];
  if (p.dim == 3) o << ", " << p.position[2][i];
  o << ") m";
  return o.str();
}

// The vertical axis is the one gravity mostly points along (y in 2D scenes, z in 3D ones).
int vertical_axis(const SimulationParameters& p) {
  int axis = p.dim - 1;
  double best = 0.0;
  for (int a = 0; a < p.dim; ++a)
    if (std::abs(p.gravity[a]) > best) best = std::abs(p.gravity[a]), axis = a;
  return axis;
}

}  // namespace

Simulation::Simulation(Model model)
    : model_(std::move(model)),
      ctx_(model_.params.dim, model_.params.d0, model_.params.h_over_d0, model_.params.rho0,
           make_periodic_box(model_.params)) {
  if (model_.params.symmetric_kernel == "wendland" ||
      (model_.params.symmetric_kernel == "auto" && model_.params.dim == 3))
    ctx_.use_wendland_symmetric_gradient();
  BuiltParticles built = washout::build_particles(model_);
  particles_ = std::move(built.particles);
  moving_walls_ = std::move(built.moving_walls);
  walls_.slip = std::move(built.wall_slip);
  // The speed a particle gains falling one spacing: slower departures from a wall are noise.
  walls_.separation_speed = std::sqrt(2.0 * model_.params.gravity.norm() * ctx_.d0);
  if (!built.bodies.empty()) {
    bodies_ = std::make_unique<RigidBodySystem>(model_, std::move(built.bodies),
                                                std::move(built.body_first));
    bodies_->place_particles(particles_);
  }
  inside_wall_.assign(particles_.fluid_count, 0);
  // "auto": the dynamic wall condition where the scene has dynamic bodies (their velocities are
  // then solved with the pressure), the Neumann form otherwise (docs/method.md).
  bool dynamic_bodies = false;
  for (std::size_t b = 0; bodies_ && b < bodies_->size(); ++b) {
    solved_bodies_.push_back(bodies_->dynamic(b));
    dynamic_bodies = dynamic_bodies || solved_bodies_.back();
  }
  walls_.dynamic = model_.params.wall_pressure == "dynamic" ||
                   (model_.params.wall_pressure == "auto" && dynamic_bodies);
  body_coupled_ = walls_.dynamic && dynamic_bodies;
  // The bodies' coupling with the pressure does not take the density term's share apart: a
  // floating box with density_kick = "positions" gained energy from its first steps.
  if (dynamic_bodies && model_.params.density_kick == "positions")
    throw SceneError(
        "density_kick = \"positions\" is not available with dynamic bodies (their coupling with "
        "the pressure keeps the density term in it); use \"velocity\"",
        "", "density_kick");

  // Domain: given, or the scene's bounding box with a generous margin (for blow-up detection).
  const auto& prm = model_.params;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    lo = lo.cwiseMin(particles_.x(i));
    hi = hi.cwiseMax(particles_.x(i));
  }
  double extent = 0.0;
  for (int a = 0; a < prm.dim; ++a) extent = std::max(extent, hi[a] - lo[a]);
  const Vec3 margin = Vec3::Constant(std::max(0.5 * extent, 10.0 * prm.h()));
  domain_lower_ = lo - margin;
  domain_upper_ = hi + margin;
  for (int a = 0; a < prm.dim; ++a) {
    if (!prm.domain_min.empty()) domain_lower_[a] = prm.domain_min[a];
    if (!prm.domain_max.empty()) domain_upper_[a] = prm.domain_max[a];
  }
  for (std::size_t i = 0; i < particles_.fluid_count; ++i)
    if (!inside_domain(particles_.x(i)))
      throw SceneError("fluid particle at " + format_point(particles_, i) +
                           " starts outside the domain (domain_min/domain_max)",
                       model_.scene_path, "domain_min");
  const double g = prm.gravity.norm();
  max_speed_limit_ =
      prm.max_speed > 0 ? prm.max_speed : std::max(10.0 * std::sqrt(2.0 * g * extent), 10.0);
  for (auto& wall : moving_walls_) {
    if (!evaluate_wall_motion(wall, 0.0))
      throw SceneError(
          "the motion of wall '" + model_.walls[wall.wall_index].name + "' is not finite at t = 0",
          model_.walls[wall.wall_index].where);
    set_wall_velocity(wall, particles_);
    set_wall_position(wall, particles_);
  }
  probe_values_.assign(model_.probes.size(), 0.0);
  // The energy budget starts from the scene as built: E(0) and the scale M_fluid |g| H.
  {
    const Vec3 down = g > 0 ? Vec3(prm.gravity / g) : Vec3::Zero();
    double lowest = std::numeric_limits<double>::max(), highest = -lowest;
    for (std::size_t i = 0; i < particles_.fluid_count; ++i) {
      const double z = -down.dot(particles_.x(i));
      lowest = std::min(lowest, z), highest = std::max(highest, z);
    }
    fluid_height_ = particles_.fluid_count > 0 ? highest - lowest + ctx_.d0 : 0.0;
    moving_boundaries_ = !moving_walls_.empty() || bodies_ != nullptr;
    const double scale = ctx_.mass * particles_.fluid_count * g * fluid_height_;
    energy_budget_.start(mechanical_energy(), scale, prm.energy_gain_limit);
  }

  // Modes resolved once from the parameters, and the step composed from what the scene uses.
  ghost_surface_ = prm.surface_pressure == "ghost";
  gradient_forms_.symmetric = prm.pressure_gradient == "symmetric";
  gradient_forms_.ghost_surface = ghost_surface_ && prm.surface_gradient == "ghost";
  // BoomerAMG's hierarchy (and pcg_agg's aggregates) serve later steps only while the system
  // keeps its size and order: with pcg_amg and pcg_agg every fluid particle keeps a row, a drop
  // breaking off or a squeeze film forming turns rows into identity rows instead of renumbering the
  // rest (a new set-up nearly every step of the 3D wash-out after the surge's impact otherwise).
  // Decided on the fluid's size (fixed for the run), the solver on the unknowns' (solve_pressure):
  // where they fall on either side of a threshold the other solvers solve the identity rows as they
  // are.
  {
    const std::string resolved =
        resolve_solver(prm.solver, prm.dim, particles_.fluid_count, body_coupled_);
    stable_ppe_rows_ = resolved == "pcg_amg" || resolved == "pcg_agg";
  }
  SceneFeatures features;
  features.bodies = bodies_ != nullptr;
  for (std::size_t b = 0; bodies_ && b < bodies_->size(); ++b)
    features.prescribed_bodies =
        features.prescribed_bodies || bodies_->model(b).motion == rigid::MotionKind::kPrescribed;
  features.dynamic_wall = walls_.dynamic;
  features.turbulence = prm.turbulence == "smagorinsky";
  features.wall_friction = prm.wall_friction == "log_law";
  features.shifting = prm.shifting > 0 || prm.shifting_with_speed > 0;
  features.surface_smoothing = prm.surface_smoothing > 0;
  features.surface_strain = prm.alpha > 0 && prm.alpha_near_surface == "strain";
  features.gradient_scale = gradient_scale_ = prm.gradient_scale == "particle";
  features.density_kick = density_kick_ = prm.density_kick == "positions";
  work_.keep_density_rhs = density_kick_;
  features.moving_walls = !moving_walls_.empty();
  features.probes = !model_.probes.empty();
  features.reorder = prm.reorder_interval > 0;
  plan_ = compose_step(features);
  layout_fingerprint_ = compute_layout_fingerprint();
}

Simulation::~Simulation() = default;

TimeStepInputs Simulation::time_step_inputs(double until) const {
  const auto& prm = model_.params;
  TimeStepInputs in;
  in.fixed_dt = prm.dt;
  in.cfl = prm.cfl, in.viscous_number = prm.viscous_number, in.dt_max = prm.dt_max;
  in.h = ctx_.h;
  in.max_speed = max_speed_;
  in.max_viscosity = prm.viscosity;
  for (double nu_t : work_.eddy_viscosity)
    in.max_viscosity = std::max(in.max_viscosity, prm.viscosity + nu_t);
  in.gravity = prm.gravity.norm();
  in.time = time_, in.until = until;
  return in;
}

// alpha for a step of the chosen length (density_relaxation.hpp): with "per_time", the step the
// default limits would take in the same state (the same inputs) is the reference. At the default
// limits the two steps are the same numbers and alpha is used as given.
double Simulation::step_alpha(const TimeStepInputs& inputs, const TimeStepChoice& choice) const {
  const auto& prm = model_.params;
  if (prm.alpha_scaling == "per_step") return prm.alpha;
  const SimulationParameters defaults;
  TimeStepInputs reference = inputs;
  reference.until = std::numeric_limits<double>::infinity();  // no landing on a frame
  reference.fixed_dt = 0.0;
  reference.cfl = defaults.cfl, reference.viscous_number = defaults.viscous_number;
  reference.dt_max = defaults.dt_max;
  return density_relaxation_per_time(prm.alpha, choice.unlanded_dt,
                                     washout::choose_time_step(reference).dt);
}

// The Courant number dt U / h of a step at the flow's speed scale: the fastest fluid particle,
// and at least the shallow-water speed sqrt(g H), so that still water has a scale too.
double Simulation::step_courant(double dt) const {
  const double speed =
      std::max(max_speed_, std::sqrt(model_.params.gravity.norm() * fluid_height_));
  return dt * speed / ctx_.h;
}

double Simulation::mechanical_energy() const {
  const Vec3& g = model_.params.gravity;
  double energy = fluid_mechanical_energy(particles_, ctx_.mass, g);
  for (std::size_t b = 0; bodies_ && b < bodies_->size(); ++b) {
    if (!bodies_->dynamic(b)) continue;
    const auto& m = bodies_->model(b);
    const auto& s = bodies_->state(b);
    const Eigen::Matrix3d R = rigid::rotation_matrix(s.orientation);
    const Vec3 Iw = R * m.inertia * R.transpose() * s.angular_velocity;
    energy += 0.5 * m.mass * s.velocity.squaredNorm() + 0.5 * s.angular_velocity.dot(Iw) -
              m.mass * g.dot(s.position);
  }
  return energy;
}

// The energy guard (energy_budget.hpp), after the step: the work bound of the moving boundaries
// over this step, then the budget.
void Simulation::check_energy(StepReport& report) {
  const auto& prm = model_.params;
  if (!(prm.energy_gain_limit > 0)) return;
  if (moving_boundaries_) {
    const double g = prm.gravity.norm();
    const double max_pressure = prm.rho0 * (g * fluid_height_ + 0.5 * max_speed_ * max_speed_);
    energy_budget_.add_work_bound(report.dt,
                                  moving_boundary_power_bound(particles_, ctx_.d0, max_pressure));
  }
  report.mechanical_energy = mechanical_energy();
  report.energy_allowed = energy_budget_.allowed(report.mechanical_energy);
  if (energy_budget_.excess(report.mechanical_energy) > 0)
    throw UnstableError(energy_budget_.describe(report.mechanical_energy, report.time));
}

StepReport Simulation::step() { return step_until(std::numeric_limits<double>::infinity()); }

StepReport Simulation::step_until(double until) {
  const auto& prm = model_.params;
  const auto wall_start = std::chrono::steady_clock::now();
  StepInProgress now;
  const TimeStepInputs inputs = time_step_inputs(until);
  const TimeStepChoice choice = washout::choose_time_step(inputs);
  now.dt = choice.dt;
  now.report.alpha = step_alpha(inputs, choice);
  now.report.dt_limit = choice.limit;
  if (prm.dt == 0 && now.dt < prm.dt_min) {
    std::ostringstream m;
    m << "the adaptive time step fell to " << now.dt << " s (set by the "
      << step_limit_name(choice.limit) << " limit), below dt_min = " << prm.dt_min << " s";
    throw UnstableError(m.str());
  }
  now.t_new = time_ + now.dt;
  for (const Stage stage : plan_) {
    auto timing = timer_.measure(stage_name(stage));
    run_stage(stage, now);
  }
  StepReport& report = now.report;
  report.wall_seconds =
      last_report_.wall_seconds +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  last_report_ = report;
  return report;
}

void Simulation::run_stage(Stage stage, StepInProgress& now) {
  const auto& prm = model_.params;
  const double dt = now.dt;
  StepReport& report = now.report;
  switch (stage) {
    case Stage::reorder:
      if (step_ % prm.reorder_interval == 0) reorder_fluid();
      return;
    case Stage::neighbours:
      grid_.build(particles_, 2.0 * ctx_.h, ctx_.periodic);
      grid_.build_list(particles_, particles_.fluid_count, 2.0 * ctx_.h, neighbors_);
      return;
    case Stage::density:
      if (gradient_scale_)
        compute_summation_density_and_gradient_moment(ctx_, neighbors_, particles_,
                                                      gradient_forms_.symmetric, work_);
      else
        compute_summation_density(ctx_, neighbors_, particles_);
      report.free_surface_particles =
          detect_free_surface(ctx_, neighbors_, particles_, prm.free_surface_threshold, work_);
      return;
    case Stage::gradient_scale:
      scale_from_gradient_moment(neighbors_, particles_, work_);  // the moments: density's walk
      return;
    case Stage::wall_markers:
      total_active_boundary_ += mark_active_boundary(neighbors_, particles_, active_boundary_);
      update_marker_velocities(ctx_, grid_, particles_, active_boundary_, walls_, work_.boundary);
      return;
    case Stage::squeeze_film:
      report.squeeze_film_particles =
          mark_squeeze_film(ctx_, neighbors_, particles_, work_.boundary);
      set_film_pressure(ctx_, neighbors_, particles_, prm.gravity, work_.free_surface,
                        work_.boundary);
      return;
    case Stage::turbulence:
      compute_eddy_viscosity(ctx_, neighbors_, particles_, prm.smagorinsky_constant, work_);
      return;
    case Stage::predictor:
      predict_velocity(ctx_, neighbors_, particles_, prm.viscosity, prm.gravity, dt, work_,
                       prm.turbulence_at_walls == "markers");
      return;
    case Stage::wall_shear:
      apply_wall_shear(ctx_, neighbors_, particles_, walls_, prm.viscosity, dt, work_);
      return;
    case Stage::moving_walls:
      for (auto& wall : moving_walls_) {
        if (!evaluate_wall_motion(wall, now.t_new))
          throw UnstableError("the motion of wall '" + model_.walls[wall.wall_index].name +
                              "' is not finite at t = " + std::to_string(now.t_new));
        set_wall_velocity(wall, particles_);
      }
      return;
    case Stage::prescribed_bodies:
      bodies_->set_prescribed_velocities(now.t_new, particles_);
      return;
    case Stage::wall_accelerations:
      update_wall_accelerations(particles_, solved_bodies_, dt, previous_wall_velocity_,
                                work_.boundary);
      return;
    case Stage::ppe_assembly:
      now.ppe = assemble_pressure_poisson(ctx_, neighbors_, particles_, prm.gravity,
                                          now.report.alpha, dt, ghost_surface_, work_, walls_,
                                          gradient_forms_.symmetric, stable_ppe_rows_);
      return;
    case Stage::ppe_solve:
      solve_pressure(now);
      return;
    case Stage::density_pressure:
      solve_density_pressure();
      return;
    case Stage::body_loads:
      if (walls_.dynamic) {
        const CouplingReport coupling =
            coupling_.couple(ctx_, neighbors_, grid_, particles_, work_, *solver_, *bodies_,
                             prm.gravity, dt, {prm.solver_tolerance, prm.coupling_tolerance});
        total_ppe_iterations_ += coupling.iterations;
      } else {
        bodies_->compute_fluid_loads(ctx_, grid_, particles_, prm.gravity);
      }
      return;
    case Stage::corrector:
      if (density_kick_)
        correct_velocity_keeping_density_kick(ctx_, neighbors_, particles_, work_, walls_,
                                              prm.gravity, dt, gradient_forms_);
      else
        correct_velocity(ctx_, neighbors_, particles_, work_, walls_, prm.gravity, dt,
                         gradient_forms_);
      return;
    case Stage::surface_smoothing:
      smooth_surface_velocity(ctx_, neighbors_, particles_, work_,
                              surface_smoothing_for_step(prm.surface_smoothing, step_courant(dt),
                                                         prm.surface_smoothing_courant),
                              shift_scratch_);
      return;
    case Stage::surface_strain:
      accumulate_surface_strain(ctx_, neighbors_, particles_, dt, work_);
      return;
    case Stage::advect:
      max_speed_ = advance_positions(ctx_, particles_, dt);
      return;
    case Stage::density_kick:
      remove_density_kick(work_, particles_);
      return;
    case Stage::shifting:
      shift_particles(ctx_, neighbors_, particles_, work_, prm.shifting, prm.shifting_with_speed,
                      dt, shift_scratch_);
      return;
    case Stage::wall_positions:
      for (auto& wall : moving_walls_) set_wall_position(wall, particles_);
      return;
    case Stage::bodies:
      report.substeps = bodies_->advance(time_, dt, prm.gravity, particles_);
      bodies_->check_overlap(prm.contact_overlap_limit * ctx_.d0);
      return;
    case Stage::clock:
      time_ = now.t_new;
      ++step_;
      report.step = step_;
      report.time = time_;
      report.dt = dt;
      report.max_speed = max_speed_;
      return;
    case Stage::checks:
      check_health(report);
      check_energy(report);
      return;
    case Stage::push_out:
      push_out_of_solids(report);
      return;
    case Stage::probes:
      evaluate_probes();
      return;
  }
}

namespace {

// A solve that fails or does not converge stops the run as unstable, saying which.
SolveReport solve_or_stop(LinearSolver& solver, const CsrMatrix& A, const std::vector<double>& b,
                          std::vector<double>& x, const std::string& what) {
  SolveReport solve;
  try {
    solve = solver.solve(A, b, x);
  } catch (const SolverError& e) {
    throw UnstableError("the " + what + " solve failed: " + e.what());
  }
  if (!solve.converged)
    throw UnstableError("the " + what + " solver did not converge in " +
                        std::to_string(solve.iterations) + " iterations (residual " +
                        std::to_string(solve.relative_residual) + ")");
  return solve;
}

}  // namespace

void Simulation::solve_pressure(StepInProgress& now) {
  const auto& prm = model_.params;
  const std::string wanted = resolve_solver(prm.solver, prm.dim, now.ppe.unknowns, body_coupled_);
  if (!solver_ || solver_->name() != wanted)
    solver_ = make_solver(wanted, prm.solver_tolerance, prm.solver_max_iterations);
  last_solver_ = wanted;
  gather_pressure_guess(particles_, work_);
  const SolveReport solve =
      solve_or_stop(*solver_, work_.matrix, work_.rhs, work_.solution, "pressure");
  scatter_pressure(work_, particles_);
  now.report.ppe_iterations = solve.iterations;
  now.report.ppe_residual = solve.relative_residual;
  now.report.ppe_unknowns = now.ppe.unknowns;
  total_ppe_iterations_ += solve.iterations;
}

// density_kick = "positions": the density term's share of the right-hand side alone, by Jacobi
// CG from zero to a loose tolerance (density_kick.cpp); its iterations count with the PPE's.
void Simulation::solve_density_pressure() {
  if (!density_solver_)
    density_solver_ =
        make_solver("pcg", kDensityKickTolerance, model_.params.solver_max_iterations);
  work_.density_solution.assign(work_.matrix.rows, 0.0);
  const SolveReport solve = solve_or_stop(*density_solver_, work_.matrix, work_.density_rhs,
                                          work_.density_solution, "density term's pressure");
  total_ppe_iterations_ += solve.iterations;
  scatter_density_pressure(work_, particles_.fluid_count, work_.density_pressure);
}

void Simulation::check_health(StepReport& report) {
  const std::size_t n = particles_.fluid_count;
  const int dim = particles_.dim;
  // The retired stay where they left, at rest: whatever the step's stages gave them goes.
  for (std::uint32_t i : retired_) {
    for (int a = 0; a < 3; ++a) particles_.velocity[a][i] = 0.0;
    particles_.pressure[i] = 0.0;
  }
  // First offending particle (lowest index) of each kind, found in parallel.
  std::size_t bad_value = n, too_fast = n, escaped = n, escaped_count = 0;
  double energy = 0.0;
  const double limit2 = max_speed_limit_ * max_speed_limit_;
#pragma omp parallel for reduction(min : bad_value, too_fast, escaped) \
    reduction(+ : energy, escaped_count)
  for (std::size_t i = 0; i < n; ++i) {
    if (particles_.retired(i)) continue;
    double s2 = 0.0;
    bool finite = true;
    for (int a = 0; a < dim; ++a) {
      const double u = particles_.velocity[a][i], x = particles_.position[a][i];
      finite = finite && std::isfinite(u) && std::isfinite(x);
      s2 += u * u;
    }
    if (!finite) bad_value = std::min(bad_value, i);
    if (s2 > limit2) too_fast = std::min(too_fast, i);
    if (!inside_domain(particles_.x(i))) escaped = std::min(escaped, i), ++escaped_count;
    energy += 0.5 * ctx_.mass * s2;
  }
  report.kinetic_energy = energy;
  std::ostringstream where;
  if (bad_value < n) {
    where << "particle " << particles_.id[bad_value] << " has a non-finite velocity or position";
    throw UnstableError(where.str());
  }
  if (too_fast < n) {
    where << "runaway velocity: particle " << particles_.id[too_fast] << " at "
          << format_point(particles_, too_fast) << " moves at "
          << std::sqrt(std::pow(particles_.velocity[0][too_fast], 2) +
                       std::pow(particles_.velocity[1][too_fast], 2) +
                       std::pow(particles_.velocity[2][too_fast], 2))
          << " m/s (limit max_speed = " << max_speed_limit_ << " m/s)";
    throw UnstableError(where.str());
  }
  if (escaped < n) retire_escaped_fluid(escaped, escaped_count, report);
  report.retired_particles = retired_.size();
  for (std::size_t b = 0; bodies_ && b < bodies_->size(); ++b) {
    const Vec3& x = bodies_->state(b).position;
    if (!inside_domain(x)) {
      where << "body '" << bodies_->name(b) << "' left the domain: its centre of mass is at ("
            << x.x() << ", " << x.y();
      if (dim == 3) where << ", " << x.z();
      where << ") m";
      throw UnstableError(where.str());
    }
  }
}

// The domain guard (docs/stability.md): fluid that leaves the domain, a drop squeezed out of a
// closing gap or spray thrown over a wall, is retired, kept in its place as kind Retired and out
// of the flow; a run losing more than escape_limit of its fluid so stops, since then the domain
// or the flow is wrong, not a drop. The first retirement is kept for the summary.
void Simulation::retire_escaped_fluid(std::size_t first, std::size_t count, StepReport& report) {
  const std::size_t n = particles_.fluid_count;
  const double limit = model_.params.escape_limit;
  const double allowed = std::floor(limit * static_cast<double>(n));
  if (static_cast<double>(retired_.size() + count) > allowed) {
    std::ostringstream m;
    m << "particle " << particles_.id[first] << " left the domain at "
      << format_point(particles_, first);
    if (count > 1) m << " (with " << count - 1 << " more this step)";
    if (!retired_.empty()) m << ", after " << retired_.size() << " retired before";
    m << ": more than escape_limit = " << limit << " of the " << n
      << " fluid particles gone; is the domain (domain_min, domain_max) too small?";
    throw UnstableError(m.str());
  }
  if (retired_.empty()) first_retirement_ = {report.time, report.step};
  for (std::size_t i = 0; i < n; ++i) {
    if (particles_.kind[i] != static_cast<std::uint8_t>(ParticleKind::Fluid) ||
        inside_domain(particles_.x(i)))
      continue;
    particles_.kind[i] = static_cast<std::uint8_t>(ParticleKind::Retired);
    for (int a = 0; a < 3; ++a) particles_.velocity[a][i] = 0.0;
    particles_.pressure[i] = 0.0;
    retired_.push_back(static_cast<std::uint32_t>(i));
  }
}

bool Simulation::inside_domain(const Vec3& x) const {
  for (int a = 0; a < particles_.dim; ++a)
    if (x[a] < domain_lower_[a] || x[a] > domain_upper_[a]) return false;
  return true;
}

std::string Simulation::describe_first_retirement() const {
  if (retired_.empty()) return "";
  std::ostringstream m;
  m << "particle " << particles_.id[retired_.front()] << " left the domain at "
    << format_point(particles_, retired_.front()) << ", t = " << first_retirement_.time
    << " s (step " << first_retirement_.step << ")";
  return m.str();
}

const MovingWall* Simulation::motion_of_wall(std::size_t w) const {
  for (const auto& wall : moving_walls_)
    if (wall.wall_index == w) return &wall;
  return nullptr;
}

void Simulation::evaluate_probes() {
  const auto& prm = model_.params;
  for (std::size_t k = 0; k < model_.probes.size(); ++k) {
    const auto& probe = model_.probes[k];
    switch (probe.quantity) {
      case ProbeSpec::Quantity::Pressure:
        probe_values_[k] = sensor_pressure(ctx_, grid_, particles_, probe);
        break;
      case ProbeSpec::Quantity::WaterHeight:
        probe_values_[k] = water_height(ctx_, particles_, vertical_axis(prm), probe);
        break;
      case ProbeSpec::Quantity::Front:
        probe_values_[k] = front_position(ctx_, particles_, prm.rho0, probe);
        break;
    }
  }
}

void Simulation::update_boundary_pressures() {
  grid_.build(particles_, 2.0 * ctx_.h, ctx_.periodic);
  // Which boundary particles see fluid, at the positions the step left.
  mark_boundary_near_fluid(ctx_, grid_, particles_, active_boundary_);
  update_wall_pressures(ctx_, grid_, model_.params.gravity, active_boundary_, particles_);
}

}  // namespace washout
