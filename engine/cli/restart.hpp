#pragma once
// `washout run SCENE.lua --restart RUN.h5`: checks that RUN.h5 is a run of this very scene
// with these parameters and reads the state of its last complete checkpoint
// (docs/reliability.md "Restart"). The run then continues in RUN.h5 itself.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "engine/io/checkpoint.hpp"
#include "engine/model/model.hpp"

namespace washout::cli {

// A run file that cannot be continued by this scene: exit 1 with the reason.
class RestartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parameters that may differ between the run and its restart: they change nothing before
// the checkpoint (end_time lets a finished run go on; threads and max_particles do not
// change the physics, although another thread count gives another rounding).
bool restart_may_change(const std::string& parameter);

// Reads RUN.h5's checkpoint after checking that its scene text and parameters are the model's
// and that its series hold the checkpoint's steps. Throws RestartError.
io::Checkpoint load_restart(const std::string& run_path, const Model& model);

// The parameters of a run file's `parameters` attribute, name -> value as JSON text.
std::vector<std::pair<std::string, std::string>> parse_parameter_json(const std::string& json);

}  // namespace washout::cli
