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
  double slip = 0.65;  // 0 no-slip, 1 free-slip
  WallMotion motion;   // empty for a fixed wall
  SourceLocation where;
  bool moving() const { return static_cast<bool>(motion); }
};

struct ProbeSpec {
  enum class Quantity { Pressure, WaterHeight, Front };
  std::string name;
  Quantity quantity = Quantity::Pressure;
  Vec3 point = Vec3::Zero();  // Pressure: where; WaterHeight: (x[, y]) and bed elevation
  int axis = 0;               // Front: the axis along which the front advances
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
  OutputSpec output;
  std::string scene_name;
  std::string scene_path;
  std::string scene_source;
};

}  // namespace washout
