#pragma once
// A run: the Model turned into particles and stepped by the stabilized ISPH projection method.
// The step is composed from what the scene uses (no turbulence stage without turbulence, no
// moving-wall update without moving walls); each stage's time is measured.
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/boundary/moving_walls.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/particle_order.hpp"
#include "engine/core/sph_context.hpp"
#include "engine/fluid/fluid_work.hpp"
#include "engine/fluid/isph_stages.hpp"
#include "engine/model/model.hpp"
#include "engine/sim/energy_budget.hpp"
#include "engine/sim/implicit_body_coupling.hpp"
#include "engine/sim/simulation_errors.hpp"
#include "engine/sim/stage_timer.hpp"
#include "engine/sim/step_plan.hpp"
#include "engine/sim/time_step_limits.hpp"
#include "engine/solvers/linear_solver.hpp"

namespace washout {

namespace io {
struct Checkpoint;
}  // namespace io
class RigidBodySystem;

struct StepReport {
  long step = 0;
  double time = 0.0;  // after the step
  double dt = 0.0;
  int ppe_iterations = 0;
  double ppe_residual = 0.0;
  std::size_t ppe_unknowns = 0;
  std::size_t free_surface_particles = 0;
  double max_speed = 0.0;
  double kinetic_energy = 0.0;
  // Fluid and dynamic bodies, kinetic + potential, and the most the budget allows now
  // (energy_budget.hpp).
  double mechanical_energy = 0.0;
  double energy_allowed = 0.0;
  StepLimit dt_limit = StepLimit::dt_max;  // which limit set dt (time_step_limits.hpp)
  double alpha = 0.0;  // the density-invariance term's relaxation this step (alpha_scaling)
  std::size_t particles_in_walls = 0;
  std::size_t squeeze_film_particles = 0;  // fluid in gaps narrower than 2 d0 at a body
  std::size_t retired_particles = 0;       // fluid that left the domain so far (cumulative)
  long substeps = 0;          // rigid-body sub-steps in this step (0: the scene has no bodies)
  double wall_seconds = 0.0;  // cumulative
};

enum class RunStatus { Completed, StoppedByScene, Unstable };

struct RunSummary {
  RunStatus status = RunStatus::Completed;
  std::string message;
  double time = 0.0;
  long steps = 0;
  std::size_t frames = 0;
  double last_frame_time = 0.0;
  double wall_seconds = 0.0;
  std::size_t fluid_particles = 0, boundary_particles = 0;
  double mean_ppe_iterations = 0.0;
  std::string pressure_solver;  // the solver of the last pressure solve ("auto" resolved)
  // Boundary (wall, gate, body) particles within a fluid particle's support, the only ones the
  // step's marker, assembly and corrector work touches; a mean over the steps.
  double mean_active_boundary = 0.0;
  long wall_crossings = 0;   // fluid particles found inside a wall, summed over steps
  long gap_relocations = 0;  // of those, moved to a free place: out of a closing gap, or put
                             // back onto another particle (free_spot.hpp)
  std::size_t retired_particles = 0;  // fluid that left the domain and was retired
  std::string first_retirement;       // the first of them: which, where, when
  long bodies_asleep_steps = 0;       // steps the bodies slept at rest (contact/body_rest.hpp)
  std::string output_path;            // where an observer keeps the run (RunObserver::kept_in)
  std::vector<std::pair<std::string, double>> stage_seconds;
};

class Simulation;

// Watches a run: the run file, the progress display, Lua callbacks, frame rendering. The engine
// reports; what is written, shown or drawn is the observer's. Each hook is called for every
// observer in the order given; the record_* hooks of all observers come before the watching
// hooks of any, so that a callback that fails leaves the steps before it recorded.
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // Before frame 0; in a restarted run (which reports no frame 0), after its state is restored.
  virtual void on_start(const Simulation&) {}
  // After each step (timed as "output").
  virtual void record_step(const Simulation&, const StepReport&) {}
  // A frame to keep (frame 0 is t = 0), the wall pressures brought up to date (timed as
  // "output"). `restart`: the full state at the frame, for a frame on the output grid, from
  // which a run continues exactly (washout run --restart); null for the frame a stop writes
  // between two.
  virtual void record_frame(const Simulation&, std::size_t /*frame_index*/,
                            const io::Checkpoint* /*restart*/) {}
  // Returning false stops the run.
  virtual bool on_step(const Simulation&, const StepReport&) { return true; }
  virtual bool on_frame(const Simulation&, std::size_t /*frame_index*/) { return true; }
  // The run ends with an exception (a scene error mid-run): what was recorded is kept. Called
  // before the exception leaves Simulation::run; what it throws is dropped.
  virtual void on_abort(const Simulation&) {}
  virtual void on_finish(const Simulation&, const RunSummary&) {}
  // Why the observer stopped the run (read after on_step/on_frame returned false).
  virtual std::string stop_reason() const { return "stopped by the scene"; }
  // Where the observer keeps the run (a run file), named in the summary and in the message of an
  // unstable run; empty: nowhere.
  virtual std::string kept_in() const { return {}; }
};

class Simulation {
 public:
  explicit Simulation(Model model);  // builds particles; throws SceneError
  ~Simulation();

  const Model& model() const { return model_; }
  const SimulationParameters& params() const { return model_.params; }
  const Particles& particles() const { return particles_; }
  const SphContext& context() const { return ctx_; }
  double time() const { return time_; }
  long step_count() const { return step_; }
  // The particles in the order the run keeps them (reorder_interval), each with its id.
  ParticleView view() const { return particles_.view(time_, model_.params.d0); }
  const StageTimer& timer() const { return timer_; }
  const std::vector<double>& probe_values() const { return probe_values_; }
  const StepReport& last_report() const { return last_report_; }
  // The stages of one step, in order, as composed from the scene (step_plan.hpp).
  const std::vector<Stage>& plan() const { return plan_; }
  // The rigid bodies and their coupling; null when the scene has none.
  const RigidBodySystem* bodies() const { return bodies_.get(); }

  // One projection step; throws UnstableError when the state blows up.
  StepReport step();
  // One step whose size is trimmed so that the run lands exactly on time `until` (a frame).
  StepReport step_until(double until);
  // Steps to end_time with a frame every output_interval, reporting steps and frames to the
  // observers (a run recorder keeps them: engine/io/run_recorder.hpp). With `resume` (a grid
  // frame's checkpoint), continues from that frame instead of starting at t = 0 (washout run
  // --restart).
  RunSummary run(const std::vector<RunObserver*>& observers,
                 const io::Checkpoint* resume = nullptr);

  // Everything the next step reads that is not rebuilt from the scene, at full precision
  // (simulation_state.cpp): particles, time-step state, wall motion, solver warm starts, bodies
  // and contact history. restore_state puts a saved state back into a Simulation built from the
  // same scene and parameters; it throws io::CheckpointError when the state does not fit.
  void save_state(io::Checkpoint& c) const;
  void restore_state(const io::Checkpoint& c);
  // A hash of the particle layout at t = 0 (kinds, groups, positions, normals, wall distances):
  // a checkpoint from a scene that builds other particles is refused.
  std::uint64_t layout_fingerprint() const { return layout_fingerprint_; }

  // The wall pressures (virtual markers) for the current state, for output and loads.
  void update_boundary_pressures();

 private:
  // What the adaptive step is chosen from (time_step_limits.hpp), to land on `until`.
  TimeStepInputs time_step_inputs(double until) const;
  // The density-invariance term's alpha for the step chosen from these inputs (alpha_scaling,
  // density_relaxation.hpp).
  double step_alpha(const TimeStepInputs& inputs, const TimeStepChoice& choice) const;
  // The Courant number dt U / h of a step at the flow's speed scale (surface smoothing's rate).
  double step_courant(double dt) const;
  // Kinetic plus potential energy of the fluid and the dynamic bodies.
  double mechanical_energy() const;
  void check_energy(StepReport& report);
  void check_health(StepReport& report);
  void retire_escaped_fluid(std::size_t first, std::size_t count, StepReport& report);
  std::string describe_first_retirement() const;
  // Within [domain_min, domain_max] along the scene's axes.
  bool inside_domain(const Vec3& x) const;
  void push_out_of_solids(StepReport& report);  // solid_push_out.cpp
  void check_wall_crossings(std::size_t new_crossings, std::size_t first) const;
  // One step's values shared by its stages.
  struct StepInProgress {
    double dt = 0.0, t_new = 0.0;
    StepReport report;  // report.alpha: the density-invariance term's relaxation this step
    PpeStatistics ppe;
  };
  void run_stage(Stage stage, StepInProgress& now);
  void solve_pressure(StepInProgress& now);
  void solve_density_pressure();
  // The motion of wall w if it moves, else nullptr (its shape then sits where it was built).
  const MovingWall* motion_of_wall(std::size_t w) const;
  // Signed distance of x from the nearest wall or body (negative inside one).
  double distance_to_solids(const Vec3& x) const;
  // Moves fluid particle i, caught in a closing gap or put back onto another particle, to the
  // nearest free place (free_spot.hpp); `nearby_first`: a hole next to it before a wide search.
  void move_to_free_place(std::size_t i, bool nearby_first);
  // Whether a particle other than i, fluid only or any, lies within d0/2 of y (push_out stage).
  bool crowded(const Vec3& y, std::size_t i, bool fluid_only) const;
  // Calls visit(x) with the position of every particle near y but i, in the grid of the start
  // of the step, skipping the fluid caught this step; those moved so far count at their new
  // places (relocated_). fluid_only leaves the boundary particles out.
  template <class Visit>
  void for_each_settled_particle_near(const Vec3& y, std::size_t i, bool fluid_only,
                                      Visit&& visit) const;
  void evaluate_probes();
  std::uint64_t compute_layout_fingerprint() const;
  // The fluid sorted by cell again (the reorder stage), and any order applied to the particles
  // and to everything held for them from step to step (fluid_reorder.cpp).
  void reorder_fluid();
  void apply_fluid_order(const FluidOrder& order);

  Model model_;
  Particles particles_;
  SphContext ctx_;
  NeighborGrid grid_;
  NeighborList neighbors_;
  WallConditions walls_;  // fixed for the run (boundary_state.hpp)
  FluidWork work_;        // refilled every step
  ImplicitBodyCoupling coupling_;
  std::array<std::vector<double>, 3> previous_wall_velocity_;  // for the wall acceleration
  std::vector<std::uint8_t> solved_bodies_;  // 1: a dynamic body, its velocity solved by coupling_
  bool body_coupled_ = false;  // dynamic bodies solved with the pressure (dynamic walls)
  std::unique_ptr<LinearSolver> solver_;
  std::string last_solver_;  // kept for the summary: solver_ is dropped at every frame
  std::vector<MovingWall> moving_walls_;
  std::unique_ptr<RigidBodySystem> bodies_;
  std::vector<std::uint8_t> active_boundary_;
  std::vector<std::uint8_t> inside_wall_;
  std::vector<std::uint8_t> trapped_;     // fluid to move to a free place this step
  std::vector<std::uint32_t> relocated_;  // of those, the ones moved out so far this step
  std::vector<double> shift_scratch_;
  bool fluid_reordered_ = false;  // some fluid particle is not at the index of its id
  StageTimer timer_;
  // The step composed from the scene (step_plan.hpp) and the modes it runs in.
  std::vector<Stage> plan_;
  bool ghost_surface_ = true;
  GradientForms gradient_forms_;
  bool gradient_scale_ = false;  // the density's walk also takes the gradient moments
  bool density_kick_ = false;    // density_kick = "positions" (density_kick.cpp)
  std::unique_ptr<LinearSolver> density_solver_;  // its loose second solve
  bool stable_ppe_rows_ = false;  // one PPE row per fluid particle (pcg_amg's reuse)
  double time_ = 0.0;
  long step_ = 0;
  std::uint64_t layout_fingerprint_ = 0;
  double max_speed_ = 0.0;
  double max_speed_limit_ = 0.0;
  // The energy guard (energy_budget.hpp): the fluid's height extent along gravity at the start
  // sets the scale M g H and the largest pressure the walls can meet.
  EnergyBudget energy_budget_;
  double fluid_height_ = 0.0;
  bool moving_boundaries_ = false;  // moving walls or bodies: the budget counts their work
  Vec3 domain_lower_, domain_upper_;
  long wall_crossings_ = 0;
  long gap_relocations_ = 0;
  std::vector<std::uint32_t> retired_;  // fluid that left the domain, in the order it left
  struct {
    double time = 0.0;
    long step = 0;
  } first_retirement_;  // when the first of retired_ left, for the summary
  long total_ppe_iterations_ = 0;
  double total_active_boundary_ = 0.0;  // boundary particles some fluid particle sees, summed
  std::vector<double> probe_values_;
  StepReport last_report_;
};

}  // namespace washout
