#pragma once
// Bounds on what a scene's Lua code may take: memory (a counting allocator refuses to grow the
// state past a limit) and time (a count hook stops a script or callback that has not returned
// within a limit). Both are set from the command line (--lua-memory-limit, --lua-time-limit).
#include <chrono>
#include <cstddef>

struct lua_State;

namespace washout::lua {

struct LuaLimitSettings {
  double memory_mib = 1024;  // the Lua state's heap, all of it
  double seconds = 60;       // for the scene script, and for each callback or motion call
};

struct LuaLimits {
  LuaLimitSettings settings;
  std::size_t used = 0;  // bytes held by the state
  bool memory_exceeded = false;
  int armed = 0;  // nesting depth of protected calls under the deadline
  std::chrono::steady_clock::time_point deadline;
};

// A fresh state (standard libraries not yet opened) using `limits` as its allocator's data.
lua_State* new_limited_state(LuaLimits& limits);
// The limits of a state made by new_limited_state, else null.
LuaLimits* limits_of(lua_State* L);

// Arms the deadline for the outermost protected call and disarms it afterwards.
class DeadlineScope {
 public:
  explicit DeadlineScope(lua_State* L);
  ~DeadlineScope();
  DeadlineScope(const DeadlineScope&) = delete;
  DeadlineScope& operator=(const DeadlineScope&) = delete;

 private:
  lua_State* L_;
  LuaLimits* limits_;
};

}  // namespace washout::lua
