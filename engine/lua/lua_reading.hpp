#pragma once
// Reading scene tables from Lua, shared by the scene's C functions (lua_scene.cpp, lua_bodies.cpp).
// Every mistake raises a Lua error whose message starts with the scene file and line.
#include <initializer_list>
#include <string>

#include "engine/core/vec3.hpp"
#include "engine/geometry/shape.hpp"
#include "engine/model/model.hpp"

struct lua_State;

namespace washout::lua::detail {

// "scenes/x.lua:12": the script line that called the current C function.
std::string where(lua_State* L);
// Raises a Lua error "file:line: message" (message usually starts with a space).
[[noreturn]] void fail(lua_State* L, const std::string& message);

// A point or vector given as {x, y} (2D) or {x, y, z} (3D).
Vec3 read_vector(lua_State* L, int index, const char* what, int dim);
double read_number(lua_State* L, int table, const char* field, const char* what, bool required,
                   double fallback);
std::string read_string(lua_State* L, int table, const char* field, const std::string& fallback);
// Rejects misspelt keys in the table argument at `table`, suggesting the nearest allowed one.
void check_keys(lua_State* L, int table, const char* what,
                std::initializer_list<const char*> allowed);
Shape read_shape(lua_State* L, int index, int dim);
// The shape of the table argument 1: its `shape` field or its first positional entry.
Shape region_shape(lua_State* L, const char* what, int dim);

// The model being built, with the parameters resolved (for a washout.* C function whose first
// upvalue is the scene binding).
Model& resolved_model(lua_State* L);

}  // namespace washout::lua::detail
