#include "engine/model/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace washout {
namespace {

using Vec = std::vector<double>;

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

const char* type_name(const ParameterValue& v) {
  if (std::holds_alternative<double>(v)) return "a number";
  if (std::holds_alternative<std::string>(v)) return "a string";
  return "a list of numbers";
}

std::string json_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (c == '\n') {
      o += "\\n";
      continue;
    }
    o += c;
  }
  return o;
}

}  // namespace

const std::vector<ParameterInfo>& ParameterSet::engine_table() {
  // Every default is the one SimulationParameters holds: one home for each.
  const SimulationParameters d;
  static const std::vector<ParameterInfo> table = {
      {"dim", "-", "space dimension, 2 or 3", double(d.dim)},
      {"d0", "m", "initial particle spacing", d.d0},
      {"h_over_d0", "-", "smoothing length h as a multiple of d0 (kernel support 2h)", d.h_over_d0},
      {"rho0", "kg/m^3", "reference density of the fluid", d.rho0},
      {"viscosity", "m^2/s", "kinematic viscosity nu", d.viscosity},
      {"gravity", "m/s^2", "gravity vector; empty = {0,-9.81} in 2D, {0,0,-9.81} in 3D", Vec{}},
      {"alpha", "-",
       "relaxation of the density-invariance term in the PPE (0 divergence-free, 1 "
       "density-invariant); calibrated by the hydrostatic test, see docs/method.md",
       d.alpha},
      {"alpha_near_surface", "-",
       "the density-invariance term within a kernel support of the free surface, where the "
       "summation density is low because the support is cut: \"strain\" (the particle's volume "
       "error there is its velocity divergence accumulated over the steps it has spent there) or "
       "\"off\" (no term in those rows, as before the sixteenth session; docs/method.md)",
       d.alpha_near_surface},
      {"alpha_scaling", "-",
       "how alpha follows the step: \"per_time\" (alpha is the fraction of the density error "
       "relaxed in a step as long as the default cfl, viscous_number and dt_max give (their "
       "rows); a shorter step, set by a smaller cfl, dt_max or dt, relaxes at the same rate "
       "in time, alpha dt / dt_default: the density term's velocity kick stays the default "
       "step's size, though more kicks a second add up in still water, docs/stability.md) or "
       "\"per_step\" (alpha per step at any step, as in the paper; docs/method.md)",
       d.alpha_scaling},
      {"density_kick", "-",
       "where the density term's share of the pressure acts: \"velocity\" (its gradient stays "
       "in the velocity, as in the paper) or \"positions\" (it moves the particles but is not "
       "kept in their velocity, so that the kicks of many short steps do not add up to motion "
       "in still water; costs a loose second solve and a second gradient a step, and the "
       "pressure written is the divergence-free part's; docs/stability.md)",
       d.density_kick},
      {"free_surface_threshold", "-",
       "a particle whose density is below this fraction of the full-support density is on the "
       "free surface and takes P = 0",
       d.free_surface_threshold},
      {"surface_pressure", "-",
       "where P = 0 holds at the free surface: \"ghost\" (d0/2 beyond the surface particles, "
       "through ghost values of the missing neighbours) or \"on_particles\" (on the surface "
       "particles themselves, half a spacing too low)",
       d.surface_pressure},
      {"dt", "s", "fixed time step; 0 = adaptive (cfl, viscous_number, dt_max)", d.dt},
      {"cfl", "-", "Courant number for the adaptive step: dt <= cfl h / max|u|", d.cfl},
      {"viscous_number", "-", "viscous limit of the adaptive step: dt <= viscous_number h^2 / nu",
       d.viscous_number},
      {"dt_max", "s", "largest adaptive step", d.dt_max},
      {"dt_min", "s", "an adaptive step below this stops the run as unstable", d.dt_min},
      {"end_time", "s", "simulated time at which the run ends", d.end_time},
      {"wall_slip", "-",
       "default wall slip ratio: 0 no-slip, 1 free-slip (the paper's 0.65 stood in for the "
       "wall friction that log_law now models)",
       d.wall_slip},
      {"wall_friction", "-",
       "\"log_law\": the first fluid layer at a wall feels the smooth-wall law-of-the-wall "
       "stress the resolved viscous term misses, times (1 - wall_slip); \"none\": viscous "
       "stress only (docs/method.md)",
       d.wall_friction},
      {"wall_layers", "-", "wall particle layers; 0 = enough to fill the kernel support",
       double(d.wall_layers)},
      {"turbulence", "-",
       "\"smagorinsky\" (sub-particle-scale eddy viscosity) or \"none\" (laminar flows)",
       d.turbulence},
      {"smagorinsky_constant", "-", "C_s of the Smagorinsky model (nu_t = (C_s d0)^2 |S|)",
       d.smagorinsky_constant},
      {"turbulence_at_walls", "-",
       "the eddy viscosity across a fluid-wall pair: \"markers\" (it acts on the markers' "
       "mirrored velocity, a wall stress of its own beside the law of the wall, several times "
       "larger at a no-slip wall) or \"wall_function\" (the pair takes the molecular viscosity "
       "only: the wall's turbulent stress is wall_friction's alone; docs/method.md)",
       d.turbulence_at_walls},
      {"solver", "-",
       "pressure solver: \"cholmod\" (direct), \"pcg\" (Jacobi-preconditioned CG, warm-started), "
       "\"pcg_agg\" (CG preconditioned by Jacobi plus a coarse correction on aggregates of "
       "neighbouring particles, warm-started), \"pcg_amg\" (CG preconditioned by a BoomerAMG "
       "V-cycle, warm-started), \"auto\" (pcg_agg below 100000 unknowns, pcg_amg from 100000; "
       "but in 2D cholmod up to 1000 unknowns, and up to 60000 where dynamic bodies are solved "
       "with the pressure; docs/performance.md)",
       d.solver},
      {"solver_tolerance", "-",
       "relative residual |b - Ax| / |b| at which pcg, pcg_agg and pcg_amg stop",
       d.solver_tolerance},
      {"coupling_tolerance", "-",
       "residual the dynamic bodies' pressure responses are solved to, relative to the largest "
       "response of their kind (pcg, pcg_agg, pcg_amg); where their share of the coupled "
       "pressure's residual then exceeds solver_tolerance, the coupled pressure is solved again "
       "and corrects the bodies' velocities (docs/bodies.md \"Coupling\")",
       d.coupling_tolerance},
      {"solver_max_iterations", "-",
       "pcg, pcg_agg and pcg_amg iteration limit; reaching it stops the run",
       double(d.solver_max_iterations)},
      {"pressure_gradient", "-",
       "corrector gradient: \"symmetric\" (momentum-conserving) or \"difference\"",
       d.pressure_gradient},
      {"gradient_scale", "-",
       "normalisation of the corrector's pressure gradient: \"particle\" (by each particle's own "
       "neighbours, so that a linear pressure's gradient is right in the disordered arrangement "
       "the flow leaves, not only on the initial lattice) or \"lattice\" (the lattice's sums "
       "alone, as before the seventeenth session: at rest the pressure settles up to 3 % low; "
       "docs/method.md)",
       d.gradient_scale},
      {"symmetric_kernel", "-",
       "kernel of the symmetric pressure gradient's pair force: \"cubic\" (the cubic spline, as "
       "every other operator), \"wendland\" (Wendland C2 of support 2 d0: a particle lattice "
       "under pressure is stable with it in 2D and 3D, where the cubic spline's 3D lattice "
       "buckles into columns) or \"auto\" (wendland in 3D, cubic in 2D; docs/method.md, "
       "fifteenth session)",
       d.symmetric_kernel},
      {"surface_gradient", "-",
       "corrector gradient of free-surface particles: \"corrected\" (the difference form with "
       "the kernel gradient correction over the present neighbours) or \"ghost\" (the "
       "difference form completed by the PPE's ghost values, so that it sees P = 0 at d0/2 "
       "beyond the surface; with surface_pressure = \"ghost\" only, else as corrected; "
       "docs/method.md, ninth session)",
       d.surface_gradient},
      {"wall_pressure", "-",
       "wall condition of the PPE: \"neumann\" (dP/dn from the fluid's relative velocity), "
       "\"dynamic\" (walls in the divergence, dP/dn = rho0 (g - a_wall).n; solves dynamic "
       "bodies with the pressure) or \"auto\" (dynamic when the scene has dynamic bodies, "
       "neumann otherwise: the default before the seventh session)",
       d.wall_pressure},
      {"shifting", "-",
       "fixed particle shifting A: delta r = -A h^2 grad C each step (Lind et al. 2012); 0 = off",
       d.shifting},
      {"shifting_with_speed", "-",
       "particle shifting in proportion to the distance moved, A_u: delta r = -A_u h u dt grad C "
       "with u the particle's speed (Skillen et al. 2013); keeps fast flows free of particle "
       "clumping and leaves still water alone; 0 = off",
       d.shifting_with_speed},
      {"surface_smoothing", "-",
       "free-surface particles move with this fraction of their neighbourhood's mean velocity "
       "each step (XSPH on the surface only; 0 = off), or with surface_smoothing_courant > 0 in "
       "a step of that Courant number: it then is a rate and the flow does not depend on the "
       "step",
       d.surface_smoothing},
      {"surface_smoothing_courant", "-",
       "0: surface_smoothing is taken every step (its damping grows as the step shrinks); > 0: "
       "the Courant number C_ref = dt U / h (U: the fastest fluid particle, at least sqrt(g H)) "
       "of the step that takes it, a step of Courant number C taking 1 - (1 - s)^(C / C_ref); "
       "0.2 with surface_gradient = \"ghost\" makes the front independent of the step (measured "
       "at dt_max 1 to 0.25 ms; docs/method.md, twelfth session)",
       d.surface_smoothing_courant},
      {"output_interval", "s", "simulated time between output frames", d.output_interval},
      {"max_speed", "m/s", "a faster particle stops the run as unstable; 0 = 10 sqrt(2 g L)",
       d.max_speed},
      {"energy_gain_limit", "-",
       "the energy guard: a run whose mechanical energy (fluid and bodies, kinetic + potential) "
       "exceeds its start plus the work moving walls and bodies can have done plus this "
       "fraction of M_fluid g H stops as unstable (docs/stability.md); 0 = off",
       d.energy_gain_limit},
      {"contact_overlap_limit", "-",
       "the contact guard: a body overlapping a wall or another body by more than this "
       "fraction of d0 after a step stops the run as unstable (docs/stability.md); 0 = off",
       d.contact_overlap_limit},
      {"wall_crossing_limit", "-",
       "the crossing guard: more fluid particles than this fraction of the fluid (and at least "
       "10) found newly inside walls or bodies after one step stop the run as unstable "
       "(docs/stability.md); 0 = off",
       d.wall_crossing_limit},
      {"periodic", "-", "periodic axes, e.g. \"x\" (needs domain_min and domain_max)", d.periodic},
      {"escape_limit", "-",
       "the domain guard: fluid particles that leave the domain are retired (kept in the "
       "frames as kind 4, out of the flow: spray thrown over a wall); more than this fraction "
       "of the fluid gone over the run stops it as unstable (docs/stability.md); 0 = the first "
       "one stops it",
       d.escape_limit},
      {"domain_min", "m",
       "lower corner of the domain; fluid leaving it is retired (escape_limit), a body "
       "leaving it stops the run; "
       "empty = bounding box of the scene plus a margin",
       Vec{}},
      {"domain_max", "m", "upper corner of the domain", Vec{}},
      {"threads", "-", "OpenMP threads; 0 = all cores (the CLI's --threads wins)",
       double(d.threads)},
      {"reorder_interval", "-",
       "steps between sorts of the fluid particles by cell in memory, so that neighbours in "
       "space stay neighbours in the arrays as the flow mixes them (docs/performance.md); the "
       "frames list particles by id whatever the order; 0 = never",
       double(d.reorder_interval)},
      {"max_particles", "-",
       "a scene whose particle count, estimated from its shapes before anything is allocated, "
       "exceeds this is refused (exit 1), so a mistyped d0 cannot exhaust the machine's memory",
       d.max_particles},
  };
  return table;
}

ParameterSet::ParameterSet() {
  for (const auto& info : engine_table()) values_[info.name] = info.default_value;
}

void ParameterSet::set(const std::string& name, const ParameterValue& value) {
  auto it = values_.find(name);
  if (it == values_.end()) {
    const std::string near = nearest_name(name);
    throw ParameterError(name, "unknown parameter '" + name + "'" +
                                   (near.empty() ? "" : " (did you mean '" + near + "'?)"));
  }
  ParameterValue v = value;
  // A single number is accepted where a list is expected and vice versa for one-element lists.
  if (std::holds_alternative<std::vector<double>>(it->second) && std::holds_alternative<double>(v))
    v = std::vector<double>{std::get<double>(v)};
  if (v.index() != it->second.index())
    throw ParameterError(name, "parameter '" + name + "' must be " + type_name(it->second) +
                                   ", not " + type_name(value));
  it->second = v;
}

void ParameterSet::set_from_text(const std::string& name, const std::string& text) {
  if (!has(name)) set(name, text);  // throws the unknown-name error with a suggestion
  const ParameterValue& current = values_.at(name);
  try {
    if (std::holds_alternative<double>(current)) {
      std::size_t used = 0;
      const double v = std::stod(text, &used);
      if (used != text.size()) throw std::invalid_argument(text);
      set(name, v);
    } else if (std::holds_alternative<std::string>(current)) {
      set(name, text);
    } else {
      std::string t = text;
      for (char& c : t)
        if (c == '{' || c == '}' || c == ',' || c == '[' || c == ']') c = ' ';
      std::istringstream in(t);
      std::vector<double> v;
      double x;
      while (in >> x) v.push_back(x);
      if (!in.eof()) throw std::invalid_argument(text);
      set(name, v);
    }
  } catch (const std::invalid_argument&) {
    throw ParameterError(name, "cannot read '" + text + "' as " + type_name(current) +
                                   " for parameter '" + name + "'");
  } catch (const std::out_of_range&) {
    throw ParameterError(name, "value '" + text + "' out of range for parameter '" + name + "'");
  }
}

void ParameterSet::declare(const std::string& name, const ParameterValue& value) {
  if (values_.count(name) && !scene_names_.count(name))
    throw ParameterError(name, "scene parameter '" + name +
                                   "' has the name of an engine parameter; choose another name");
  values_[name] = value;
  scene_names_.insert(name);
}

const ParameterValue& ParameterSet::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw ParameterError(name, "unknown parameter '" + name + "'");
  return it->second;
}

double ParameterSet::number(const std::string& name) const {
  const auto& v = get(name);
  if (!std::holds_alternative<double>(v))
    throw ParameterError(name, "parameter '" + name + "' must be a number");
  return std::get<double>(v);
}

std::string ParameterSet::text(const std::string& name) const {
  const auto& v = get(name);
  if (!std::holds_alternative<std::string>(v))
    throw ParameterError(name, "parameter '" + name + "' must be a string");
  return std::get<std::string>(v);
}

std::vector<double> ParameterSet::vector(const std::string& name) const {
  const auto& v = get(name);
  if (!std::holds_alternative<std::vector<double>>(v))
    throw ParameterError(name, "parameter '" + name + "' must be a list of numbers");
  return std::get<std::vector<double>>(v);
}

std::string ParameterSet::nearest_name(const std::string& name) const {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(3, name.size() / 3) + 1;
  for (const auto& [candidate, value] : values_) {
    const std::size_t d = edit_distance(name, candidate);
    if (d < best_distance) best_distance = d, best = candidate;
  }
  return best;
}

std::vector<std::string> ParameterSet::names() const {
  std::vector<std::string> n;
  for (const auto& kv : values_) n.push_back(kv.first);
  return n;
}

std::string ParameterSet::to_json() const {
  std::ostringstream o;
  o << std::setprecision(17) << "{";
  bool first = true;
  for (const auto& [name, value] : values_) {
    o << (first ? "" : ", ") << "\"" << json_escape(name) << "\": ";
    first = false;
    if (auto d = std::get_if<double>(&value)) {
      if (std::isfinite(*d))
        o << *d;
      else
        o << "null";
    } else if (auto s = std::get_if<std::string>(&value)) {
      o << "\"" << json_escape(*s) << "\"";
    } else {
      const auto& v = std::get<std::vector<double>>(value);
      o << "[";
      for (std::size_t k = 0; k < v.size(); ++k) o << (k ? ", " : "") << v[k];
      o << "]";
    }
  }
  o << "}";
  return o.str();
}

SimulationParameters SimulationParameters::from(const ParameterSet& set) {
  SimulationParameters p;
  auto positive = [&](const char* name) {
    const double v = set.number(name);
    if (!(v > 0) || !std::isfinite(v))
      throw ParameterError(
          name, std::string("parameter '") + name + "' must be positive, got " + std::to_string(v));
    return v;
  };
  auto non_negative = [&](const char* name) {
    const double v = set.number(name);
    if (!(v >= 0) || !std::isfinite(v))
      throw ParameterError(name, std::string("parameter '") + name +
                                     "' must be zero or positive, got " + std::to_string(v));
    return v;
  };
  auto in_unit_interval = [&](const char* name) {
    const double v = set.number(name);
    if (!(v >= 0 && v <= 1))
      throw ParameterError(name, std::string("parameter '") + name + "' must lie in [0, 1], got " +
                                     std::to_string(v));
    return v;
  };
  auto integer = [&](const char* name, double v) {
    if (v != std::floor(v))
      throw ParameterError(name, std::string("parameter '") + name + "' must be a whole number");
    return static_cast<int>(v);
  };
  auto one_of = [&](const char* name, std::initializer_list<const char*> allowed) {
    const std::string v = set.text(name);
    std::string list;
    for (const char* a : allowed) {
      if (v == a) return v;
      list += std::string(list.empty() ? "" : ", ") + "\"" + a + "\"";
    }
    throw ParameterError(name, std::string("parameter '") + name + "' must be one of " + list +
                                   ", got \"" + v + "\"");
  };

  p.dim = integer("dim", set.number("dim"));
  if (p.dim != 2 && p.dim != 3) throw ParameterError("dim", "parameter 'dim' must be 2 or 3");
  p.d0 = positive("d0");
  p.h_over_d0 = positive("h_over_d0");
  if (p.h_over_d0 < 0.9 || p.h_over_d0 > 2.5)
    throw ParameterError("h_over_d0", "parameter 'h_over_d0' must lie in [0.9, 2.5]");
  p.rho0 = positive("rho0");
  p.viscosity = non_negative("viscosity");
  const auto g = set.vector("gravity");
  if (g.empty()) {
    p.gravity = p.dim == 2 ? Vec3(0, -9.81, 0) : Vec3(0, 0, -9.81);
  } else {
    if (static_cast<int>(g.size()) != p.dim)
      throw ParameterError("gravity", "parameter 'gravity' needs " + std::to_string(p.dim) +
                                          " components in " + std::to_string(p.dim) + "D");
    p.gravity = Vec3(g[0], g[1], p.dim == 3 ? g[2] : 0.0);
  }
  p.alpha = non_negative("alpha");
  if (p.alpha > 1) throw ParameterError("alpha", "parameter 'alpha' must lie in [0, 1]");
  p.alpha_near_surface = one_of("alpha_near_surface", {"strain", "off"});
  p.alpha_scaling = one_of("alpha_scaling", {"per_time", "per_step"});
  p.density_kick = one_of("density_kick", {"velocity", "positions"});
  p.free_surface_threshold = in_unit_interval("free_surface_threshold");
  p.surface_pressure = one_of("surface_pressure", {"ghost", "on_particles"});
  p.dt = non_negative("dt");
  p.cfl = positive("cfl");
  p.viscous_number = positive("viscous_number");
  p.dt_max = positive("dt_max");
  p.dt_min = positive("dt_min");
  p.end_time = positive("end_time");
  p.wall_slip = in_unit_interval("wall_slip");
  p.wall_friction = one_of("wall_friction", {"log_law", "none"});
  p.wall_layers = integer("wall_layers", non_negative("wall_layers"));
  p.turbulence = one_of("turbulence", {"none", "smagorinsky"});
  p.smagorinsky_constant = non_negative("smagorinsky_constant");
  p.turbulence_at_walls = one_of("turbulence_at_walls", {"markers", "wall_function"});
  p.solver = one_of("solver", {"auto", "cholmod", "pcg", "pcg_agg", "pcg_amg"});
  p.solver_tolerance = positive("solver_tolerance");
  p.coupling_tolerance = positive("coupling_tolerance");
  p.solver_max_iterations = integer("solver_max_iterations", positive("solver_max_iterations"));
  p.pressure_gradient = one_of("pressure_gradient", {"symmetric", "difference"});
  p.gradient_scale = one_of("gradient_scale", {"particle", "lattice"});
  p.symmetric_kernel = one_of("symmetric_kernel", {"auto", "cubic", "wendland"});
  p.surface_gradient = one_of("surface_gradient", {"corrected", "ghost"});
  p.wall_pressure = one_of("wall_pressure", {"auto", "neumann", "dynamic"});
  p.shifting = non_negative("shifting");
  p.shifting_with_speed = non_negative("shifting_with_speed");
  p.surface_smoothing = in_unit_interval("surface_smoothing");
  p.surface_smoothing_courant = non_negative("surface_smoothing_courant");
  p.output_interval = positive("output_interval");
  // Every frame (and the end) is reached by at least one step, and an adaptive step may not be
  // shorter than dt_min: a frame or an end sooner than that would stop the run as "unstable".
  for (const char* name : {"output_interval", "end_time"}) {
    const double v = set.number(name);
    if (p.dt == 0 && v < p.dt_min) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "parameter '%s' = %g s is shorter than dt_min = %g s, the shortest step an "
                    "adaptive run may take",
                    name, v, p.dt_min);
      throw ParameterError(name, text);
    }
  }
  p.max_speed = non_negative("max_speed");
  p.energy_gain_limit = non_negative("energy_gain_limit");
  p.contact_overlap_limit = non_negative("contact_overlap_limit");
  p.wall_crossing_limit = non_negative("wall_crossing_limit");
  p.escape_limit = non_negative("escape_limit");
  p.periodic = set.text("periodic");
  for (char c : p.periodic)
    if (c != 'x' && c != 'y' && c != 'z')
      throw ParameterError("periodic", "parameter 'periodic' lists axes among x, y, z");
  p.domain_min = set.vector("domain_min");
  p.domain_max = set.vector("domain_max");
  for (const auto* name : {"domain_min", "domain_max"}) {
    const auto& v = std::string(name) == "domain_min" ? p.domain_min : p.domain_max;
    if (!v.empty() && static_cast<int>(v.size()) != p.dim)
      throw ParameterError(name, std::string("parameter '") + name + "' needs " +
                                     std::to_string(p.dim) + " components");
  }
  if (!p.periodic.empty() && (p.domain_min.empty() || p.domain_max.empty()))
    throw ParameterError("periodic", "periodic axes need domain_min and domain_max");
  p.threads = integer("threads", non_negative("threads"));
  p.reorder_interval = integer("reorder_interval", non_negative("reorder_interval"));
  p.max_particles = positive("max_particles");
  return p;
}

}  // namespace washout
