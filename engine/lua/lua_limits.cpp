#include "engine/lua/lua_limits.hpp"

#include <cstdio>
#include <cstdlib>
#include <lua.hpp>
#include <string>

namespace washout::lua {
namespace {

// Checking the clock every few thousand instructions costs nothing measurable.
constexpr int kHookInterval = 10000;

void* limited_alloc(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
  auto* limits = static_cast<LuaLimits*>(ud);
  const std::size_t old = ptr ? osize : 0;  // for a new block osize is the object's type
  if (nsize == 0) {
    std::free(ptr);
    limits->used -= old;
    return nullptr;
  }
  const double limit_bytes = limits->settings.memory_mib * 1024.0 * 1024.0;
  if (nsize > old && double(limits->used - old + nsize) > limit_bytes) {
    limits->memory_exceeded = true;  // Lua raises LUA_ERRMEM; shrinking never fails
    return nullptr;
  }
  void* grown = std::realloc(ptr, nsize);
  if (grown) limits->used = limits->used - old + nsize;
  return grown;
}

void deadline_hook(lua_State* L, lua_Debug*) {
  LuaLimits* limits = limits_of(L);
  if (!limits || limits->armed == 0) return;
  if (std::chrono::steady_clock::now() < limits->deadline) return;
  // From now on every instruction fails, so a pcall in the script cannot swallow the stop.
  lua_sethook(L, deadline_hook, LUA_MASKCOUNT, 1);
  // The line being run when the time ran out (level 0 in a hook is the interrupted function).
  std::string where;
  lua_Debug ar;
  if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "Sl", &ar) && ar.currentline > 0)
    where = std::string(ar.short_src) + ":" + std::to_string(ar.currentline) + ": ";
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", limits->settings.seconds);
  lua_pushfstring(L, "%sthe scene's Lua code did not return within %s s (--lua-time-limit)",
                  where.c_str(), seconds);
  lua_error(L);
}

int panic(lua_State* L) {
  const char* m = lua_tostring(L, -1);
  std::fprintf(stderr, "error: unprotected Lua error: %s\n", m ? m : "(no message)");
  std::_Exit(1);
}

}  // namespace

lua_State* new_limited_state(LuaLimits& limits) {
  lua_State* L = lua_newstate(limited_alloc, &limits);
  if (!L) return nullptr;
  lua_atpanic(L, panic);
  lua_sethook(L, deadline_hook, LUA_MASKCOUNT, kHookInterval);
  return L;
}

LuaLimits* limits_of(lua_State* L) {
  void* ud = nullptr;
  return lua_getallocf(L, &ud) == limited_alloc ? static_cast<LuaLimits*>(ud) : nullptr;
}

DeadlineScope::DeadlineScope(lua_State* L) : L_(L), limits_(limits_of(L)) {
  if (!limits_) return;
  if (limits_->armed++ == 0)
    limits_->deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(limits_->settings.seconds));
}

DeadlineScope::~DeadlineScope() {
  if (!limits_) return;
  if (--limits_->armed == 0) lua_sethook(L_, deadline_hook, LUA_MASKCOUNT, kHookInterval);
}

}  // namespace washout::lua
