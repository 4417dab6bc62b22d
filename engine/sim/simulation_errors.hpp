#pragma once
// The two ways a run ends early, as exceptions: the scene is wrong (exit 1) or the simulation
// became unstable (exit 2). Code that only reports or catches them includes this, not the
// whole simulation.
#include <stdexcept>
#include <string>
#include <utility>

namespace washout {

// The scene cannot be run as given (caught before the first step). `where` names the scene
// location and `parameter` the offending parameter when known.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& message, std::string where = "", std::string parameter = "")
      : std::runtime_error(message), where_(std::move(where)), parameter_(std::move(parameter)) {}
  const std::string& where() const { return where_; }
  const std::string& parameter() const { return parameter_; }

 private:
  std::string where_, parameter_;
};

// The simulation blew up: NaN, runaway speed, particles leaving the domain, solver failure.
class UnstableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace washout
