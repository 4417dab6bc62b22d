#pragma once
// Loads a Lua 5.4 scene script into an engine Model (docs/scenes.md is the user reference).
// The Lua state stays alive for the run: wall motions and per-step/per-frame callbacks are Lua
// functions. Errors name the scene file, the line and the parameter.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/lua/lua_limits.hpp"
#include "engine/lua/lua_validation.hpp"
#include "engine/model/model.hpp"
#include "engine/sim/simulation.hpp"

struct lua_State;

namespace washout::lua {

// Renderer settings a scene asked for with washout.frames{...} (applied by the CLI).
struct FrameRequest {
  bool enabled = false;
  int width = 1280, height = 720, every = 1;
  std::string color = "speed";
  bool fixed_range = false;
  double range_min = 0, range_max = 1;
  std::string camera_preset = "auto";
  bool camera_explicit = false;
  double camera_position[3] = {0, 0, 0}, camera_target[3] = {0, 0, 0}, camera_up[3] = {0, 0, 1};
  double camera_fov = 35;
  int camera_region_components = 0;  // 0: no region; else 2 or 3 (render_options.hpp)
  double camera_region_min[3] = {0, 0, 0}, camera_region_max[3] = {0, 0, 0};
};

using Overrides = std::vector<std::pair<std::string, std::string>>;

class LuaScene {
 public:
  // Runs the scene script with the --set overrides; throws SceneError on any mistake.
  // `limits` bounds the memory and the time of the scene's Lua code (lua_limits.hpp).
  LuaScene(const std::string& path, const Overrides& overrides,
           const LuaLimitSettings& limits = {});
  ~LuaScene();
  LuaScene(const LuaScene&) = delete;
  LuaScene& operator=(const LuaScene&) = delete;

  Model& model() { return model_; }
  const FrameRequest& frames() const { return frames_; }
  // Calls the scene's on_step / on_frame functions; null if the scene has none.
  RunObserver* callbacks();
  // The scores the scene declared with washout.validation{...} (lua_validation.hpp).
  bool validates() const { return !validation_.empty(); }
  std::vector<ValidationScore> score(const std::string& run_file) {
    return validation_.evaluate(L_, run_file);
  }

  // Implementation detail shared with the Lua C functions.
  struct Binding;

 private:
  std::unique_ptr<LuaLimits> limits_;  // outlives L_, whose allocator uses it
  lua_State* L_ = nullptr;
  Model model_;
  FrameRequest frames_;
  SceneValidation validation_;
  std::unique_ptr<RunObserver> callbacks_;
  std::unique_ptr<Binding> binding_;
};

}  // namespace washout::lua
