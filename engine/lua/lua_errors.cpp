#include "engine/lua/lua_errors.hpp"

#include <cmath>
#include <cstdio>
#include <lua.hpp>

#include "engine/lua/lua_limits.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::lua::detail {
namespace {

// What a non-string error value says about itself.
std::string describe_value(lua_State* L, int index) {
  switch (lua_type(L, index)) {
    case LUA_TNIL:
    case LUA_TNONE:
      return "error raised without a message";
    case LUA_TNUMBER:
      return "error raised with the number " + number_text(lua_tonumber(L, index)) +
             " instead of a message";
    case LUA_TBOOLEAN:
      return std::string("error raised with the boolean ") +
             (lua_toboolean(L, index) ? "true" : "false") + " instead of a message";
    default:
      break;
  }
  // A table or userdata with __tostring says what it is; anything else only its type.
  if (luaL_getmetafield(L, index, "__tostring") != LUA_TNIL) {
    lua_pop(L, 1);
    lua_pushvalue(L, index);
    lua_pushcclosure(
        L, [](lua_State* Ls) { return luaL_tolstring(Ls, 1, nullptr), 1; }, 0);
    lua_insert(L, -2);
    if (lua_pcall(L, 1, 1, 0) == LUA_OK && lua_type(L, -1) == LUA_TSTRING) {
      std::string text = lua_tostring(L, -1);
      lua_pop(L, 1);
      return text;
    }
    lua_pop(L, 1);
  }
  return std::string("error raised with a ") + luaL_typename(L, index) + " instead of a message";
}

// Message handler: strings already carry "file:line:" when Lua knew it; other values get the
// innermost Lua line on the stack.
int add_location(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING) return 1;
  std::string text = describe_value(L, 1);
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline > 0) {
      text = std::string(ar.short_src) + ":" + std::to_string(ar.currentline) + ": " + text;
      break;
    }
  }
  lua_pushstring(L, text.c_str());
  return 1;
}

}  // namespace

int protected_call(lua_State* L, int nargs, int nresults) {
  const DeadlineScope deadline(L);
  const int base = lua_gettop(L) - nargs;  // the function's slot
  lua_pushcfunction(L, add_location);
  lua_insert(L, base);
  const int status = lua_pcall(L, nargs, nresults, base);
  lua_remove(L, base);
  return status;
}

std::string pop_error(lua_State* L, int status) {
  std::string text;
  LuaLimits* limits = limits_of(L);
  if (status == LUA_ERRMEM && limits && limits->memory_exceeded)
    text = "the scene's Lua code went over its memory limit of " +
           number_text(limits->settings.memory_mib) + " MiB (--lua-memory-limit)";
  else if (lua_type(L, -1) == LUA_TSTRING)
    text = lua_tostring(L, -1);
  else if (status == LUA_ERRMEM)
    text = "not enough memory";
  else
    text = describe_value(L, -1);
  lua_pop(L, 1);
  if (limits) limits->memory_exceeded = false;
  return text;
}

std::string number_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

Vec3 returned_vector(lua_State* L, int index, int n, const std::string& what) {
  index = lua_absindex(L, index);
  const std::string expected = what + " must be a list of " + std::to_string(n) + " numbers";
  if (!lua_istable(L, index)) throw SceneError(expected + ", got a " + luaL_typename(L, index));
  const lua_Integer length = luaL_len(L, index);
  if (length != n) throw SceneError(expected + ", got " + std::to_string(length) + " entries");
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < n; ++k) {
    const int type = lua_geti(L, index, k + 1);
    const double x = lua_tonumber(L, -1);
    lua_pop(L, 1);
    if (type != LUA_TNUMBER)
      throw SceneError(expected + ", entry " + std::to_string(k + 1) + " is not a number");
    if (!std::isfinite(x))
      throw SceneError(what + " must be finite, entry " + std::to_string(k + 1) + " is " +
                       number_text(x));
    v[k] = x;
  }
  return v;
}

}  // namespace washout::lua::detail
