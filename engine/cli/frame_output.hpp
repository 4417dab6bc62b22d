#pragma once
// Renders PNG frames during `washout run` at each output frame the scene asked for
// (washout.frames{...}), through the renderer's read-only particle view.
#include <memory>
#include <string>

#include "engine/lua/lua_scene.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::cli {

std::unique_ptr<RunObserver> make_frame_output(const lua::FrameRequest& request,
                                               const std::string& folder);

}  // namespace washout::cli
