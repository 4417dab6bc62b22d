#pragma once
// Every parameter a scene can set, with its unit, documented default and meaning (the table in
// parameters.cpp is the single source; docs/parameters.md is generated from it by
// `washout run --list-parameters`). Scenes may also declare parameters of their own; all are
// overridable from the shell with --set NAME=VALUE.
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "engine/core/vec3.hpp"

namespace washout {

using ParameterValue = std::variant<double, std::string, std::vector<double>>;

struct ParameterInfo {
  const char* name;
  const char* unit;
  const char* doc;
  ParameterValue default_value;
};

// A parameter that is missing, misspelt or out of range. `name` is the parameter's name.
class ParameterError : public std::runtime_error {
 public:
  ParameterError(std::string name, const std::string& message)
      : std::runtime_error(message), name_(std::move(name)) {}
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

class ParameterSet {
 public:
  static const std::vector<ParameterInfo>& engine_table();

  ParameterSet();  // engine defaults
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  bool is_scene_parameter(const std::string& name) const { return scene_names_.count(name) != 0; }
  // Sets a known parameter; throws ParameterError for unknown names (suggesting the nearest) or
  // a value of the wrong type.
  void set(const std::string& name, const ParameterValue& value);
  // Parses a shell value ("0.3", "{0,-9.81}", "pcg") to the parameter's type, then sets it.
  void set_from_text(const std::string& name, const std::string& text);
  // Declares a scene-specific parameter with its default.
  void declare(const std::string& name, const ParameterValue& value);
  const ParameterValue& get(const std::string& name) const;
  double number(const std::string& name) const;
  std::string text(const std::string& name) const;
  std::vector<double> vector(const std::string& name) const;
  std::string nearest_name(const std::string& name) const;
  std::vector<std::string> names() const;
  std::string to_json() const;

 private:
  std::map<std::string, ParameterValue> values_;
  std::set<std::string> scene_names_;
};

// The engine's parameters, typed and checked for physical sense.
struct SimulationParameters {
  int dim = 2;
  double d0 = 0.01;
  double h_over_d0 = 1.2;
  double rho0 = 1000.0;
  double viscosity = 1e-6;  // kinematic, m^2/s
  Vec3 gravity = Vec3(0, -9.81, 0);
  double alpha = 0.05;
  // The density-invariance term within a support of the free surface, where the summation
  // density is low because the support is cut: "strain" measures the volume error there by the
  // particle's accumulated velocity divergence; "off" leaves those rows without the term
  // (docs/method.md, sixteenth session).
  std::string alpha_near_surface = "strain";
  // "per_time": alpha is the fraction of the density error relaxed in a step of the default
  // limits' length, and a shorter step relaxes at the same rate in time (alpha dt / dt_default);
  // "per_step": alpha per step at any step (docs/method.md, thirty-fourth session).
  std::string alpha_scaling = "per_time";
  // "velocity": the density term's pressure gradient stays in the velocity, as in the paper;
  // "positions": it moves the particles but is not kept in their velocity, which costs a loose
  // second solve and gradient a step and keeps still water still at any step
  // (engine/fluid/density_kick.cpp; docs/stability.md, forty-sixth session).
  std::string density_kick = "velocity";
  double free_surface_threshold = 0.9;
  std::string surface_pressure = "ghost";
  double dt = 0.0;  // 0: adaptive
  double cfl = 0.3;
  double viscous_number = 0.125;
  double dt_max = 1e-3;
  double dt_min = 1e-7;
  double end_time = 1.0;
  // Walls hold the fluid by the law of the wall on no-slip markers, and the sub-particle eddy
  // viscosity carries that stress into the surge's tip (docs/method.md, "the seventh session").
  double wall_slip = 0.0;
  std::string wall_friction = "log_law";
  int wall_layers = 0;  // 0: enough to fill the kernel support
  std::string turbulence = "smagorinsky";
  double smagorinsky_constant = 0.12;
  // Whether the eddy viscosity also acts across wall pairs, on the markers' mirrored velocity
  // ("markers"), or the wall's turbulent stress is the law of the wall's alone ("wall_function";
  // docs/method.md, the thirty-third session).
  std::string turbulence_at_walls = "markers";
  std::string solver = "auto";
  // The loosest tolerance that moves no validated figure (docs/performance.md).
  double solver_tolerance = 1e-6;
  double coupling_tolerance = 1e-2;  // body coupling's response solves, first pass
  int solver_max_iterations = 5000;
  std::string pressure_gradient = "symmetric";
  // The corrector's gradient normalised by each particle's own neighbours ("particle") or by the
  // lattice's sums alone ("lattice"; docs/method.md, seventeenth session).
  std::string gradient_scale = "particle";
  // The symmetric gradient's pair force: "cubic" (METHOD.md's kernel), "wendland" (Wendland C2
  // of support 2 d0, whose lattice under pressure is stable in 3D) or "auto" (wendland in 3D,
  // where the cubic spline's lattice buckles; cubic in 2D, where it is neutral and the bodies'
  // figures are better with it; docs/method.md, fifteenth session).
  std::string symmetric_kernel = "auto";
  // "ghost" holds the surface without smoothing and floats bodies at their draft, but moves the
  // validated surges (docs/method.md, ninth and twelfth sessions): an option.
  std::string surface_gradient = "corrected";
  // Walls in the divergence for every scene: the Neumann form made thin films on no-slip walls
  // alternate and blow up (docs/method.md).
  std::string wall_pressure = "dynamic";
  double shifting = 0.0;
  double shifting_with_speed = 2.0;
  double surface_smoothing = 0.5;          // fraction per step, or per step of Courant number ...
  double surface_smoothing_courant = 0.0;  // ... this, a rate (0: per step; docs/method.md)
  double output_interval = 0.05;
  double max_speed = 0.0;              // 0: automatic from gravity and domain size
  double energy_gain_limit = 0.1;      // energy guard tolerance, a fraction of M g H; 0: off
  double contact_overlap_limit = 0.5;  // contact guard: deepest overlap / d0; 0: off
  double wall_crossing_limit = 0.02;   // crossing guard: fluid fraction entering solids in a step
  double escape_limit = 0.01;  // fluid fraction that may leave the domain (retired) over a run
  std::string periodic;        // axes, e.g. "x"
  std::vector<double> domain_min, domain_max;
  int threads = 0;
  // Steps between sorts of the fluid by cell in memory (particle_order.hpp); 0: never.
  int reorder_interval = 50;
  double max_particles = 5e7;  // refused above this estimate before allocating

  double h() const { return h_over_d0 * d0; }
  // Wall particle layers: wall_layers, or enough to fill the kernel support (ceil(2h / d0)).
  int wall_layer_count() const {
    return wall_layers > 0 ? wall_layers : static_cast<int>(std::ceil(2.0 * h() / d0 - 1e-9));
  }
  static SimulationParameters from(const ParameterSet& set);
};

}  // namespace washout
