#pragma once
// Turning any Lua error value into a message. A script may raise error({}), error(), error(42):
// such values carry no text and no position, so the calls below add both where Lua knows them.
#include <string>

#include "engine/core/vec3.hpp"

struct lua_State;

namespace washout::lua::detail {

// lua_pcall with a message handler that turns a non-string error value into text prefixed
// with the file and line that raised it. On failure the top of the stack holds a string.
int protected_call(lua_State* L, int nargs, int nresults);

// The error message at the top of the stack (whatever its type), popped.
std::string pop_error(lua_State* L, int status);

// A number as %g would print it: small values stay readable (1e-07, not 0.000000).
std::string number_text(double v);

// The table at `index` as exactly `n` finite numbers, else SceneError "<what> must ...".
Vec3 returned_vector(lua_State* L, int index, int n, const std::string& what);

}  // namespace washout::lua::detail
