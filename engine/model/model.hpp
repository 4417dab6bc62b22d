#pragma once
// The model: everything about a run that does not change while it runs (MuJoCo's Model/Data
// split). The scene loader fills it; the Simulation turns it into particles and state.
#include <functional>
#include <string>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/geometry/shape.hpp"
#include "engine/model/parameters.hpp"

namespace washout {

// Where in a scene file something was defined ("scenes/x.lua:12"), for error messages.
using SourceLocation = std::string;

struct FluidRegion {
  Shape shape;
  Vec3 velocity = Vec3::Zero();
  SourceLocation where;
};

// Prescribed wall motion: displacement from the initial position and velocity at time t.
using WallMotion = std::function<void(double t, Vec3& displacement, Vec3& velocity)>;

struct WallSpec {
  std::string name;
  Shape shape;
  double slip = SimulationParameters{}.wall_slip;  // 0 no-slip, 1 free-slip
  WallMotion motion;                               // empty for a fixed wall
  std::string material;  // contact material (MaterialSpec name); empty: "default"
  SourceLocation where;
  bool moving() const { return static_cast<bool>(motion); }
};

// A contact material (METHOD.md Contact). Defaults: the paper's PLA girder.
struct MaterialSpec {
  std::string name;
  double young_modulus = 5.0e9;  // E [Pa]
  double poisson_ratio = 0.28;   // nu [-]
  double restitution = 0.8;      // eps [-]
  SourceLocation where;
};

// Friction (and optionally restitution) of one pair of materials; pairs not listed: mu = 0,
// eps = sqrt(eps_a eps_b).
struct FrictionSpec {
  std::string material_a, material_b;
  double friction = 0.0;    // mu [-]
  double restitution = -1;  // eps [-]; < 0: not set
  SourceLocation where;
};

// Settings of the DEM contact law and its sub-stepping (docs/rigid_bodies.md "Parameters").
struct ContactSpec {
  std::string law = "linear";           // "linear" or "hertz"
  std::string damping_mass = "shared";  // "shared" (M / N_c) or "whole_body" (M)
  bool allow_tension = true;
  double steps_per_contact = 20.0;
  long max_substeps = 1000000;
  // Fluid steps all dynamic bodies must stay still, balanced and dry before they sleep (0: never;
  // docs/rigid_bodies.md "Rest").
  int rest_steps = 10;
};

// A prescribed body pose at time t, relative to the body's initial pose: the displacement of
// its centre of mass and the rotation vector (axis times angle, world frame), with their rates.
struct BodyPose {
  Vec3 displacement = Vec3::Zero();
  Vec3 rotation = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
};
using BodyMotion = std::function<BodyPose(double t)>;

// A rigid body built from a shape (docs/bodies.md). Mass from `density` or `mass` (exactly one
// is positive; 2D: per metre of thickness).
struct BodySpec {
  enum class Motion { Dynamic, Fixed, Prescribed };
  std::string name;
  Shape shape;
  double density = 0.0;                            // [kg/m^dim]
  double mass = 0.0;                               // [kg] (2D: kg/m)
  std::string material;                            // contact material; empty: "default"
  double slip = SimulationParameters{}.wall_slip;  // slip ratio of its surface for the fluid
  Motion motion = Motion::Dynamic;
  BodyMotion prescribed;                 // Motion::Prescribed
  Vec3 velocity = Vec3::Zero();          // initial, of the centre of mass
  Vec3 angular_velocity = Vec3::Zero();  // initial, world frame (2D: about z)
  Vec3 angle_axis = Vec3::UnitZ();       // unit axis of the reported rotation angle
  SourceLocation where;
};

struct ProbeSpec {
  enum class Quantity { Pressure, WaterHeight, Front };
  std::string name;
  Quantity quantity = Quantity::Pressure;
  Vec3 point = Vec3::Zero();   // Pressure: where; WaterHeight: (x[, y]) and bed elevation
  int axis = 0;                // Front: the axis along which the front advances
  Vec3 facing = Vec3::Zero();  // Pressure: the sensor face's unit normal, into the fluid; zero:
                               // the fluid on every side counts
  // WaterHeight: what the gauge reads, the top of the water standing on the bed (a camera, a
  // gauge read by eye) or the length of its vertical line under water (a resistance or
  // capacitance wire).
  enum class Gauge { Surface, WettedLength };
  Gauge gauge = Gauge::Surface;
  SourceLocation where;
};

struct OutputSpec {
  std::vector<std::string> fields = {"position", "velocity", "pressure", "kind", "id", "body"};
  std::string file_name;  // default: <scene name>.h5
};

struct Model {
  SimulationParameters params;
  ParameterSet parameter_set;  // every resolved parameter, written to the output as JSON
  std::vector<FluidRegion> fluids;
  std::vector<WallSpec> walls;
  std::vector<ProbeSpec> probes;
  std::vector<BodySpec> bodies;  // empty: no rigid-body or contact stage is built
  std::vector<MaterialSpec> materials;
  std::vector<FrictionSpec> frictions;
  ContactSpec contact;
  OutputSpec output;
  std::string scene_name;
  std::string scene_path;
  std::string scene_source;
};

}  // namespace washout
