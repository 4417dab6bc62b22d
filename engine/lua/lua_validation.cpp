#include "engine/lua/lua_validation.hpp"

#include <cctype>
#include <cstdlib>
#include <lua.hpp>

#include "engine/io/run_file_reader.hpp"
#include "engine/lua/lua_errors.hpp"
#include "engine/lua/lua_reading.hpp"

namespace washout::lua {
namespace {

using detail::check_keys;
using detail::fail;

const io::RunFileReader& reader(lua_State* L) {
  return *static_cast<const io::RunFileReader*>(lua_touserdata(L, lua_upvalueindex(1)));
}

void push_list(lua_State* L, const std::vector<double>& v) {
  lua_createtable(L, static_cast<int>(v.size()), 0);
  for (std::size_t k = 0; k < v.size(); ++k) {
    lua_pushnumber(L, v[k]);
    lua_seti(L, -2, static_cast<lua_Integer>(k + 1));
  }
}

// Rows of a [count, columns] array as a list of lists.
void push_rows(lua_State* L, const std::vector<double>& v, std::size_t columns) {
  const std::size_t rows = columns ? v.size() / columns : 0;
  lua_createtable(L, static_cast<int>(rows), 0);
  for (std::size_t r = 0; r < rows; ++r) {
    lua_createtable(L, static_cast<int>(columns), 0);
    for (std::size_t c = 0; c < columns; ++c) {
      lua_pushnumber(L, v[r * columns + c]);
      lua_seti(L, -2, static_cast<lua_Integer>(c + 1));
    }
    lua_seti(L, -2, static_cast<lua_Integer>(r + 1));
  }
}

// Run-file errors become Lua errors, so the error function's caller sees them as a failure.
template <class F>
int guarded(lua_State* L, F&& f) {
  std::string message;
  try {
    return f();
  } catch (const io::RunFileError& e) {
    message = e.what();
  }
  lua_pushstring(L, message.c_str());
  return lua_error(L);
}

// run.series("/probes/front/time"): a dataset flattened row-major; rows for 2-D datasets.
int l_series(lua_State* L) {
  const std::string path = luaL_checkstring(L, 1);
  return guarded(L, [&] {
    const auto& r = reader(L);
    const auto shape = r.shape(path);
    const auto values = r.read_doubles(path);
    if (shape.size() >= 2)
      push_rows(L, values, shape[1]);
    else
      push_list(L, values);
    return 1;
  });
}

// run.probe("front") returns two lists: time and value.
int l_probe(lua_State* L) {
  const std::string name = luaL_checkstring(L, 1);
  return guarded(L, [&] {
    const auto& r = reader(L);
    if (!r.has("/probes/" + name))
      throw io::RunFileError(r.path() + ": no probe named '" + name + "' (declare it with " +
                             "washout.probe{name = \"" + name + "\", ...})");
    push_list(L, r.read_doubles("/probes/" + name + "/time"));
    push_list(L, r.read_doubles("/probes/" + name + "/value"));
    return 2;
  });
}

// run.frame(k): frame k (0 the initial state, -1 the last) as {time, step, position = {{x, y},
// ...}, velocity, pressure, kind}; fields the run did not write are absent.
int l_frame(lua_State* L) {
  const lua_Integer k = luaL_optinteger(L, 1, -1);
  return guarded(L, [&] {
    const auto& r = reader(L);
    const auto count = static_cast<lua_Integer>(r.frame_count());
    const lua_Integer index = k < 0 ? count + k : k;
    if (index < 0 || index >= count)
      throw io::RunFileError(r.path() + ": no frame " + std::to_string(k) + " (the file has " +
                             std::to_string(count) + ")");
    const io::FrameData f = r.read_frame(static_cast<std::size_t>(index));
    lua_newtable(L);
    lua_pushnumber(L, f.time);
    lua_setfield(L, -2, "time");
    lua_pushinteger(L, f.step);
    lua_setfield(L, -2, "step");
    push_rows(L, f.position, f.dim);
    lua_setfield(L, -2, "position");
    if (!f.velocity.empty()) {
      push_rows(L, f.velocity, f.dim);
      lua_setfield(L, -2, "velocity");
    }
    if (!f.pressure.empty()) {
      push_list(L, f.pressure);
      lua_setfield(L, -2, "pressure");
    }
    lua_createtable(L, static_cast<int>(f.kind.size()), 0);
    for (std::size_t p = 0; p < f.kind.size(); ++p) {
      lua_pushinteger(L, f.kind[p]);
      lua_seti(L, -2, static_cast<lua_Integer>(p + 1));
    }
    lua_setfield(L, -2, "kind");
    return 1;
  });
}

// run.frame_times(): the time of every frame, in order.
int l_frame_times(lua_State* L) {
  return guarded(L, [&] {
    push_list(L, reader(L).frame_times());
    return 1;
  });
}

int l_has(lua_State* L) {
  const std::string path = luaL_checkstring(L, 1);
  lua_pushboolean(L, reader(L).has(path));
  return 1;
}

// The read-only view of the run file handed to each error function.
void push_run(lua_State* L, const io::RunFileReader& r) {
  lua_newtable(L);
  lua_pushstring(L, r.path().c_str());
  lua_setfield(L, -2, "file");
  lua_pushinteger(L, r.dim());
  lua_setfield(L, -2, "dim");
  lua_pushnumber(L, r.d0());
  lua_setfield(L, -2, "d0");
  lua_pushinteger(L, static_cast<lua_Integer>(r.frame_count()));
  lua_setfield(L, -2, "frame_count");
  const std::pair<const char*, lua_CFunction> functions[] = {{"series", l_series},
                                                             {"probe", l_probe},
                                                             {"frame", l_frame},
                                                             {"frame_times", l_frame_times},
                                                             {"has", l_has}};
  for (const auto& [name, f] : functions) {
    lua_pushlightuserdata(L, const_cast<io::RunFileReader*>(&r));
    lua_pushcclosure(L, f, 1);
    lua_setfield(L, -2, name);
  }
}

}  // namespace

std::string reference_dir() {
  if (const char* env = std::getenv("WASHOUT_REFERENCE")) return env;
  return WASHOUT_REFERENCE_DIR;
}

// washout.validation{name = "front", metric = "...", reference = "...", bound = 0.1,
//                    error = function(run) ... return number end}
int SceneValidation::l_validation(lua_State* L) {
  auto* self = static_cast<SceneValidation*>(lua_touserdata(L, lua_upvalueindex(1)));
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.validation", {"name", "metric", "reference", "bound", "error"});
  Entry e;
  e.score.name = detail::read_string(L, 1, "name", self->entries_.empty() ? "error" : "");
  if (e.score.name.empty()) fail(L, " washout.validation: a second score needs a 'name'");
  for (const char c : e.score.name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
      fail(L, " washout.validation: name '" + e.score.name + "' may hold letters, digits and _");
  for (const auto& other : self->entries_)
    if (other.score.name == e.score.name)
      fail(L, " washout.validation: a score named '" + e.score.name + "' exists already");
  e.score.metric = detail::read_string(L, 1, "metric", "");
  e.score.reference = detail::read_string(L, 1, "reference", "");
  if (e.score.metric.empty() || e.score.reference.empty())
    fail(L, " washout.validation: 'metric' and 'reference' must say what the error is against");
  e.score.bound = detail::read_number(L, 1, "bound", "washout.validation", false, e.score.bound);
  lua_getfield(L, 1, "error");
  if (!lua_isfunction(L, -1))
    fail(L, " washout.validation: 'error' must be a function(run) returning the error");
  e.function_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  self->entries_.push_back(e);
  return 0;
}

void SceneValidation::install(lua_State* L) {
  lua_pushlightuserdata(L, this);
  lua_pushcclosure(L, l_validation, 1);
  lua_setfield(L, -2, "validation");
  lua_pushstring(L, reference_dir().c_str());
  lua_setfield(L, -2, "reference_dir");
}

std::vector<ValidationScore> SceneValidation::evaluate(lua_State* L,
                                                       const std::string& run_file) const {
  std::vector<ValidationScore> scores;
  io::RunFileReader r(run_file);
  for (const Entry& e : entries_) {
    ValidationScore s = e.score;
    lua_rawgeti(L, LUA_REGISTRYINDEX, e.function_ref);
    push_run(L, r);
    if (const int status = detail::protected_call(L, 1, 1); status != LUA_OK) {
      s.failure = detail::pop_error(L, status);
      lua_pushnil(L);  // balances the pop below
    } else if (!lua_isnumber(L, -1)) {
      s.failure = "the error function of '" + s.name + "' returned no number";
    } else {
      s.error = lua_tonumber(L, -1);
    }
    lua_pop(L, 1);
    scores.push_back(s);
  }
  return scores;
}

}  // namespace washout::lua
