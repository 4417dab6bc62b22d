#include "engine/lua/lua_scene.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <lua.hpp>
#include <set>
#include <sstream>

#include "engine/lua/lua_bodies.hpp"
#include "engine/lua/lua_errors.hpp"
#include "engine/lua/lua_reading.hpp"
#include "engine/lua/scene_checks.hpp"

namespace washout::lua {
namespace detail {

std::string where(lua_State* L) {
  luaL_where(L, 1);
  std::string w = lua_tostring(L, -1);
  lua_pop(L, 1);
  while (!w.empty() && (w.back() == ' ' || w.back() == ':')) w.pop_back();
  return w;
}

[[noreturn]] void fail(lua_State* L, const std::string& message) {
  luaL_where(L, 1);  // "file:line: "
  const std::size_t skip = !message.empty() && message[0] == ' ' ? 1 : 0;
  lua_pushstring(L, message.c_str() + skip);
  lua_concat(L, 2);
  lua_error(L);
  std::abort();  // unreachable: lua_error does not return
}

}  // namespace detail
using namespace detail;

struct LuaScene::Binding {
  LuaScene* scene = nullptr;
  lua_State* L = nullptr;
  Overrides overrides;
  ParameterSet set;
  bool resolved = false;
  int on_step_ref = LUA_NOREF, on_frame_ref = LUA_NOREF;
  bool stop_requested = false;
  std::string stop_reason;

  std::unique_ptr<SceneError> pending;  // a C++ error to rethrow once Lua has unwound

  int dim() const { return scene->model_.params.dim; }
  FrameRequest& frames() { return scene->frames_; }

  // Raises a Lua error for a mistake found outside the script (a --set value): Lua unwinds,
  // then the loader rethrows the SceneError with its own location.
  [[noreturn]] void raise(lua_State* Ls, SceneError error) {
    pending = std::make_unique<SceneError>(std::move(error));
    lua_pushstring(Ls, pending->what());
    lua_error(Ls);
    std::abort();
  }

  // Resolves parameters: scene values, then --set overrides, then physical checks.
  void resolve(lua_State* Ls, int table_index) {
    std::set<std::string> from_scene;
    if (table_index != 0) {
      lua_pushnil(Ls);
      while (lua_next(Ls, table_index) != 0) {
        if (lua_type(Ls, -2) != LUA_TSTRING) fail(Ls, " washout.parameters: keys must be names");
        const std::string name = lua_tostring(Ls, -2);
        if (name == "scene") {
          if (!lua_istable(Ls, -1)) fail(Ls, " washout.parameters: 'scene' must be a table");
          const int scene_table = lua_gettop(Ls);
          lua_pushnil(Ls);
          while (lua_next(Ls, scene_table) != 0) {
            if (lua_type(Ls, -2) != LUA_TSTRING)
              fail(Ls, " washout.parameters: the keys of 'scene' must be names");
            const std::string sname = lua_tostring(Ls, -2);
            try {
              set.declare(sname, to_value(Ls, -1, sname));
            } catch (const ParameterError& e) {
              fail(Ls, std::string(" ") + e.what());
            }
            lua_pop(Ls, 1);
          }
        } else {
          try {
            set.set(name, to_value(Ls, -1, name));
          } catch (const ParameterError& e) {
            fail(Ls, std::string(" ") + e.what());
          }
          from_scene.insert(name);
        }
        lua_pop(Ls, 1);
      }
    }
    for (const auto& [name, text] : overrides) {
      try {
        set.set_from_text(name, text);
      } catch (const ParameterError& e) {
        raise(Ls, SceneError(std::string("--set ") + name + "=" + text + ": " + e.what(),
                             "command line", name));
      }
    }
    try {
      scene->model_.params = SimulationParameters::from(set);
    } catch (const ParameterError& e) {
      bool overridden = false;
      for (const auto& o : overrides) overridden = overridden || o.first == e.name();
      if (overridden)
        raise(Ls, SceneError(std::string("--set ") + e.name() + ": " + e.what(), "command line",
                             e.name()));
      fail(Ls, std::string(" ") + e.what());
    }
    // NaN passes every range check (all comparisons are false), so it is refused by name here.
    if (const std::string bad = non_finite_parameter(set); !bad.empty()) {
      const std::string m = "parameter '" + bad + "' must be finite (no NaN or inf)";
      for (const auto& o : overrides)
        if (o.first == bad) raise(Ls, SceneError("--set " + bad + ": " + m, "command line", bad));
      fail(Ls, " " + m);
    }
    scene->model_.parameter_set = set;
    resolved = true;
  }

  void ensure_resolved(lua_State* Ls) {
    if (!resolved) resolve(Ls, 0);
  }

  static ParameterValue to_value(lua_State* Ls, int index, const std::string& name) {
    switch (lua_type(Ls, index)) {
      case LUA_TNUMBER:
        return lua_tonumber(Ls, index);
      case LUA_TSTRING:
        return std::string(lua_tostring(Ls, index));
      case LUA_TTABLE: {
        std::vector<double> v;
        const lua_Integer n = luaL_len(Ls, index);
        for (lua_Integer k = 1; k <= n; ++k) {
          lua_geti(Ls, index, k);
          if (!lua_isnumber(Ls, -1))
            throw ParameterError(name, "parameter '" + name + "' must be a list of numbers");
          v.push_back(lua_tonumber(Ls, -1));
          lua_pop(Ls, 1);
        }
        return v;
      }
      case LUA_TBOOLEAN:
        throw ParameterError(
            name, "parameter '" + name + "' is a boolean; use 1 or 0 (Lua treats 0 as true)");
      default:
        throw ParameterError(name, "parameter '" + name + "' must be a number, string or list");
    }
  }

  void push_parameters(lua_State* Ls) const {
    lua_newtable(Ls);
    for (const auto& name : set.names()) {
      const auto& v = set.get(name);
      if (auto d = std::get_if<double>(&v)) {
        lua_pushnumber(Ls, *d);
      } else if (auto s = std::get_if<std::string>(&v)) {
        lua_pushstring(Ls, s->c_str());
      } else {
        const auto& list = std::get<std::vector<double>>(v);
        lua_createtable(Ls, static_cast<int>(list.size()), 0);
        for (std::size_t k = 0; k < list.size(); ++k) {
          lua_pushnumber(Ls, list[k]);
          lua_seti(Ls, -2, static_cast<lua_Integer>(k + 1));
        }
      }
      lua_setfield(Ls, -2, name.c_str());
    }
    // The resolved gravity vector, whatever the default was.
    const auto& g = scene->model_.params.gravity;
    lua_createtable(Ls, dim(), 0);
    for (int a = 0; a < dim(); ++a) {
      lua_pushnumber(Ls, g[a]);
      lua_seti(Ls, -2, a + 1);
    }
    lua_setfield(Ls, -2, "gravity");
  }
};

namespace {

LuaScene::Binding* binding(lua_State* L) {
  return static_cast<LuaScene::Binding*>(lua_touserdata(L, lua_upvalueindex(1)));
}

}  // namespace

namespace detail {

Model& resolved_model(lua_State* L) {
  auto* b = binding(L);
  b->ensure_resolved(L);
  return b->scene->model();
}

// A point or vector given as {x, y} (2D) or {x, y, z} (3D).
Vec3 read_vector(lua_State* L, int index, const char* what, int dim) {
  if (!lua_istable(L, index))
    fail(L, std::string(" ") + what + " must be a list of " + std::to_string(dim) + " numbers");
  const lua_Integer n = luaL_len(L, index);
  if (n != dim)
    fail(L, std::string(" ") + what + " must have " + std::to_string(dim) + " components in " +
                std::to_string(dim) + "D, got " + std::to_string(n));
  Vec3 v = Vec3::Zero();
  for (int a = 0; a < dim; ++a) {
    lua_geti(L, index, a + 1);
    if (!lua_isnumber(L, -1)) fail(L, std::string(" ") + what + " must hold numbers");
    v[a] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  return v;
}

double read_number(lua_State* L, int table, const char* field, const char* what, bool required,
                   double fallback) {
  lua_getfield(L, table, field);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    if (required) fail(L, std::string(" ") + what + ": missing '" + field + "'");
    return fallback;
  }
  if (!lua_isnumber(L, -1)) fail(L, std::string(" ") + what + ": '" + field + "' must be a number");
  const double v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

std::string read_string(lua_State* L, int table, const char* field, const std::string& fallback) {
  lua_getfield(L, table, field);
  std::string v = fallback;
  if (lua_isstring(L, -1))
    v = lua_tostring(L, -1);
  else if (!lua_isnil(L, -1))
    fail(L, std::string(" '") + field + "' must be a string");
  lua_pop(L, 1);
  return v;
}

// Rejects misspelt keys in a table argument: the nearest allowed key is suggested.
void check_keys(lua_State* L, int table, const char* what,
                std::initializer_list<const char*> allowed) {
  lua_pushnil(L);
  while (lua_next(L, table) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) != LUA_TSTRING) continue;  // positional entries
    const std::string key = lua_tostring(L, -1);
    bool ok = false;
    for (const char* a : allowed) ok = ok || key == a;
    if (!ok) {
      ParameterSet names;  // reuse the edit-distance search over the allowed keys
      std::string list, best;
      std::size_t best_d = 100;
      for (const char* a : allowed) {
        list += std::string(list.empty() ? "" : ", ") + a;
        std::size_t d = 0;
        const std::string s = a;
        // cheap distance: length difference plus mismatched positions
        for (std::size_t k = 0; k < std::max(s.size(), key.size()); ++k)
          d += (k >= s.size() || k >= key.size() || s[k] != key[k]) ? 1 : 0;
        if (d < best_d) best_d = d, best = s;
      }
      lua_pop(L, 1);
      fail(L, std::string(" ") + what + ": unknown key '" + key + "'" +
                  (best_d <= 3 ? " (did you mean '" + best + "'?)" : "") + "; allowed: " + list);
    }
  }
}

Shape read_shape(lua_State* L, int index, int dim);

Shape read_shape_list(lua_State* L, int index, int dim) {
  Shape s;
  const lua_Integer n = luaL_len(L, index);
  for (lua_Integer k = 1; k <= n; ++k) {
    lua_geti(L, index, k);
    s.add(read_shape(L, lua_gettop(L), dim));
    lua_pop(L, 1);
  }
  return s;
}

Shape read_shape(lua_State* L, int index, int dim) {
  index = lua_absindex(L, index);
  if (!lua_istable(L, index))
    fail(L, " expected a shape (washout.box{...}, washout.cylinder{...})");
  lua_getfield(L, index, "kind");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    if (luaL_len(L, index) > 0) return read_shape_list(L, index, dim);
    fail(L, " expected a shape (washout.box{...}, washout.cylinder{...}, washout.union{...})");
  }
  if (lua_type(L, -1) != LUA_TSTRING)
    fail(L, std::string(" a shape's 'kind' must be a string (\"box\", \"cylinder\", \"sphere\", "
                        "\"union\"), got a ") +
                luaL_typename(L, -1));
  const std::string kind = lua_tostring(L, -1);
  lua_pop(L, 1);
  if (kind != "union" && kind != "box" && kind != "cylinder" && kind != "sphere")
    fail(L, " unknown shape kind '" + kind + "' (box, cylinder, sphere, union)");
  if (kind == "union") {
    lua_getfield(L, index, "parts");
    Shape s = read_shape_list(L, lua_gettop(L), dim);
    lua_pop(L, 1);
    return s;
  }
  if (kind == "box") {
    lua_getfield(L, index, "min");
    const Vec3 lo = read_vector(L, -1, "box min", dim);
    lua_getfield(L, index, "max");
    const Vec3 hi = read_vector(L, -1, "box max", dim);
    lua_pop(L, 2);
    return Shape::box(lo, hi);
  }
  lua_getfield(L, index, "center");
  const Vec3 c = read_vector(L, -1, (kind + " center").c_str(), dim);
  lua_pop(L, 1);
  const double r = read_number(L, index, "radius", kind.c_str(), true, 0);
  if (kind == "sphere") return Shape::sphere(c, r);
  const double length = read_number(L, index, "length", "cylinder", dim == 3, 0);
  const std::string axis = read_string(L, index, "axis", "z");
  return Shape::cylinder(c, r, length, axis == "x" ? 0 : axis == "y" ? 1 : 2);
}

// The shape of a region: the table's `shape` field or its first positional entry.
Shape region_shape(lua_State* L, const char* what, int dim) {
  lua_getfield(L, 1, "shape");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_geti(L, 1, 1);
  }
  if (lua_isnil(L, -1)) fail(L, std::string(" ") + what + ": missing 'shape'");
  Shape s = read_shape(L, -1, dim);
  lua_pop(L, 1);
  return s;
}

}  // namespace detail

namespace {

// Shape constructors return plain tables so that Lua helpers can inspect and build on them.
int l_box(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.box", {"min", "max"});
  auto* b = binding(L);
  b->ensure_resolved(L);
  lua_getfield(L, 1, "min");
  const Vec3 lo = read_vector(L, -1, "box min", b->dim());
  lua_getfield(L, 1, "max");
  const Vec3 hi = read_vector(L, -1, "box max", b->dim());
  lua_pop(L, 2);
  for (int a = 0; a < b->dim(); ++a)
    if (!(lo[a] < hi[a]))
      fail(L, std::string(" washout.box: min must be below max along ") + char('x' + a));
  lua_newtable(L);
  lua_pushstring(L, "box");
  lua_setfield(L, -2, "kind");
  lua_getfield(L, 1, "min");
  lua_setfield(L, -2, "min");
  lua_getfield(L, 1, "max");
  lua_setfield(L, -2, "max");
  return 1;
}

int l_round_shape(lua_State* L, const char* kind) {
  luaL_checktype(L, 1, LUA_TTABLE);
  auto* b = binding(L);
  b->ensure_resolved(L);
  if (std::string(kind) == "cylinder")
    check_keys(L, 1, "washout.cylinder", {"center", "radius", "length", "axis"});
  else
    check_keys(L, 1, "washout.sphere", {"center", "radius"});
  if (!(read_number(L, 1, "radius", kind, true, 0) > 0))
    fail(L, std::string(" ") + kind + ": radius must be positive");
  lua_pushvalue(L, 1);
  lua_pushstring(L, kind);
  lua_setfield(L, -2, "kind");
  (void)read_shape(L, -1, b->dim());  // validates now, with this line in the error
  return 1;
}
int l_cylinder(lua_State* L) { return l_round_shape(L, "cylinder"); }
int l_sphere(lua_State* L) { return l_round_shape(L, "sphere"); }

int l_union(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_newtable(L);
  lua_pushstring(L, "union");
  lua_setfield(L, -2, "kind");
  lua_pushvalue(L, 1);
  lua_setfield(L, -2, "parts");
  return 1;
}

Shape region_shape(lua_State* L, const char* what) {
  return detail::region_shape(L, what, binding(L)->dim());
}

int l_parameters(lua_State* L) {
  auto* b = binding(L);
  if (b->resolved) fail(L, " washout.parameters must be called once, before any geometry");
  luaL_checktype(L, 1, LUA_TTABLE);
  b->resolve(L, 1);
  b->push_parameters(L);
  return 1;
}

int l_fluid(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.fluid", {"shape", "velocity"});
  auto* b = binding(L);
  b->ensure_resolved(L);
  FluidRegion r;
  r.shape = region_shape(L, "washout.fluid");
  r.where = where(L);
  lua_getfield(L, 1, "velocity");
  if (!lua_isnil(L, -1)) r.velocity = read_vector(L, -1, "fluid velocity", b->dim());
  lua_pop(L, 1);
  b->scene->model().fluids.push_back(r);
  return 0;
}

// A moving wall's motion: t -> displacement {dx, dy[, dz]} and optionally its velocity, each
// checked on every call (length, numbers, finite) so that a slip in the script is not read as 0.
WallMotion make_motion(lua_State* L, int ref, std::string name, int dim) {
  return [L, ref, name, dim](double t, Vec3& displacement, Vec3& velocity) {
    auto call = [&](double time, Vec3* vel) {
      const std::string what = "motion of wall '" + name + "' at t = " + number_text(time);
      lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
      lua_pushnumber(L, time);
      const int status = protected_call(L, 1, 2);
      if (status != LUA_OK) throw SceneError(what + " failed: " + pop_error(L, status));
      bool has_velocity = false;
      Vec3 d = Vec3::Zero();
      try {
        d = returned_vector(L, -2, dim, what + ": the displacement");
        if (!lua_isnil(L, -1)) {
          const Vec3 v = returned_vector(L, -1, dim, what + ": the velocity");
          if (vel) *vel = v, has_velocity = true;
        }
      } catch (...) {
        lua_pop(L, 2);
        throw;
      }
      lua_pop(L, 2);
      return std::make_pair(d, has_velocity);
    };
    auto [d, has_velocity] = call(t, &velocity);
    displacement = d;
    if (!has_velocity) {  // central difference; exact for the quadratic free-fall gate
      const double delta = 1e-6;
      const double t0 = std::max(0.0, t - delta), t1 = t + delta;
      velocity = (call(t1, nullptr).first - call(t0, nullptr).first) / (t1 - t0);
    }
  };
}

int add_wall(lua_State* L, bool moving) {
  luaL_checktype(L, 1, LUA_TTABLE);
  if (moving)
    check_keys(L, 1, "washout.moving_wall", {"shape", "name", "slip", "motion", "material"});
  else
    check_keys(L, 1, "washout.wall", {"shape", "name", "slip", "material"});
  auto* b = binding(L);
  b->ensure_resolved(L);
  auto& model = b->scene->model();
  WallSpec w;
  w.shape = region_shape(L, moving ? "washout.moving_wall" : "washout.wall");
  w.name = read_string(L, 1, "name",
                       (moving ? "moving_wall_" : "wall_") + std::to_string(model.walls.size()));
  w.slip = read_number(L, 1, "slip", "wall", false, model.params.wall_slip);
  if (!(w.slip >= 0 && w.slip <= 1)) fail(L, " wall '" + w.name + "': slip must lie in [0, 1]");
  w.material = read_string(L, 1, "material", "");
  if (!w.material.empty() && !material_defined(L, w.material.c_str()))
    fail(L, " wall '" + w.name + "': unknown material '" + w.material +
                "' (define it with washout.material before)");
  w.where = where(L);
  if (moving) {
    lua_getfield(L, 1, "motion");
    if (!lua_isfunction(L, -1))
      fail(L, " washout.moving_wall: 'motion' must be a function of time");
    const int ref = luaL_ref(L, LUA_REGISTRYINDEX);
    w.motion = make_motion(L, ref, w.name, b->dim());
  }
  model.walls.push_back(std::move(w));
  return 0;
}
int l_wall(lua_State* L) { return add_wall(L, false); }
int l_moving_wall(lua_State* L) { return add_wall(L, true); }

int l_probe(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.probe", {"name", "quantity", "at", "axis", "facing", "reads"});
  auto* b = binding(L);
  b->ensure_resolved(L);
  ProbeSpec p;
  p.where = where(L);
  p.name = read_string(L, 1, "name", "");
  if (p.name.empty()) fail(L, " washout.probe: missing 'name'");
  for (const auto& other : b->scene->model().probes)
    if (other.name == p.name)
      fail(L, " washout.probe: a probe named '" + p.name + "' exists already");
  const std::string q = read_string(L, 1, "quantity", "pressure");
  if (q == "pressure")
    p.quantity = ProbeSpec::Quantity::Pressure;
  else if (q == "water_height")
    p.quantity = ProbeSpec::Quantity::WaterHeight;
  else if (q == "front")
    p.quantity = ProbeSpec::Quantity::Front;
  else
    fail(L, " washout.probe: quantity must be \"pressure\", \"water_height\" or \"front\", got \"" +
                q + "\"");
  if (p.quantity != ProbeSpec::Quantity::Front) {
    lua_getfield(L, 1, "at");
    p.point = read_vector(L, -1, "probe 'at'", b->dim());
    lua_pop(L, 1);
  } else {
    const std::string axis = read_string(L, 1, "axis", "x");
    if (axis != "x" && axis != "y" && axis != "z")
      fail(L, " washout.probe: axis must be x, y or z");
    p.axis = axis[0] - 'x';
  }
  lua_getfield(L, 1, "reads");
  if (!lua_isnil(L, -1)) {
    if (p.quantity != ProbeSpec::Quantity::WaterHeight)
      fail(L,
           " washout.probe: 'reads' (what a wave gauge measures) is for a water_height probe "
           "only");
    const std::string reads = read_string(L, 1, "reads", "surface");
    if (reads == "surface")
      p.gauge = ProbeSpec::Gauge::Surface;
    else if (reads == "wetted_length")
      p.gauge = ProbeSpec::Gauge::WettedLength;
    else
      fail(L,
           " washout.probe: reads must be \"surface\" (the top of the water standing on the "
           "bed) or \"wetted_length\" (the length of the gauge's line under water), got \"" +
               reads + "\"");
  }
  lua_pop(L, 1);
  lua_getfield(L, 1, "facing");
  if (!lua_isnil(L, -1)) {
    if (p.quantity != ProbeSpec::Quantity::Pressure)
      fail(L, " washout.probe: 'facing' (the sensor face's normal) is for a pressure probe only");
    const Vec3 facing = read_vector(L, -1, "probe 'facing'", b->dim());
    if (!(facing.norm() > 0.0) || !std::isfinite(facing.norm()))
      fail(L,
           " washout.probe: 'facing' must be a nonzero vector (the sensor face's normal, "
           "pointing into the fluid)");
    p.facing = facing.normalized();
  }
  lua_pop(L, 1);
  b->scene->model().probes.push_back(p);
  return 0;
}

int l_output(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.output", {"file", "fields"});
  auto* b = binding(L);
  auto& out = b->scene->model().output;
  out.file_name = read_string(L, 1, "file", out.file_name);
  lua_getfield(L, 1, "fields");
  if (lua_istable(L, -1)) {
    out.fields.clear();
    const std::set<std::string> known = {"position", "velocity", "pressure", "kind", "id", "body"};
    for (lua_Integer k = 1; k <= luaL_len(L, -1); ++k) {
      lua_geti(L, -1, k);
      const std::string f = lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
      if (!known.count(f))
        fail(L, " washout.output: unknown field '" + f +
                    "' (fields: position, velocity, pressure, kind, id, body)");
      out.fields.push_back(f);
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  return 0;
}

// camera = { region = { min = {x, y[, z]}, max = {x, y[, z]} } }: the box the view is fitted to.
void read_camera_region(lua_State* L, int region, FrameRequest& f) {
  if (!lua_istable(L, region))
    fail(L, " washout.frames: camera region must be { min = ..., max = ... }");
  check_keys(L, region, "camera region", {"min", "max"});
  lua_getfield(L, region, "min");
  const int n = lua_istable(L, -1) ? static_cast<int>(luaL_len(L, -1)) : 0;
  if (n != 2 && n != 3)
    fail(L, " washout.frames: camera region min must be a list of 2 (2D) or 3 (3D) numbers");
  const Vec3 lo = read_vector(L, -1, "camera region min", n);
  lua_pop(L, 1);
  lua_getfield(L, region, "max");
  const Vec3 hi = read_vector(L, -1, "camera region max", n);
  lua_pop(L, 1);
  for (int a = 0; a < n; ++a) {
    if (!(hi[a] > lo[a]))
      fail(L, std::string(" washout.frames: camera region max must exceed min along ") +
                  char('x' + a));
    f.camera_region_min[a] = lo[a], f.camera_region_max[a] = hi[a];
  }
  f.camera_region_components = n;
}

int l_frames(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.frames", {"width", "height", "color", "every", "camera", "range"});
  auto& f = binding(L)->frames();
  f.enabled = true;
  f.width = static_cast<int>(read_number(L, 1, "width", "washout.frames", false, f.width));
  f.height = static_cast<int>(read_number(L, 1, "height", "washout.frames", false, f.height));
  f.every = static_cast<int>(read_number(L, 1, "every", "washout.frames", false, f.every));
  if (f.width < 16 || f.height < 16 || f.every < 1)
    fail(L, " washout.frames: width and height must be at least 16 and every at least 1");
  f.color = read_string(L, 1, "color", f.color);
  lua_getfield(L, 1, "range");
  if (lua_istable(L, -1)) {
    const Vec3 r = read_vector(L, -1, "frames range", 2);
    f.fixed_range = true, f.range_min = r[0], f.range_max = r[1];
  }
  lua_pop(L, 1);
  lua_getfield(L, 1, "camera");
  if (lua_istable(L, -1)) {
    const int cam = lua_gettop(L);
    f.camera_preset = read_string(L, cam, "preset", f.camera_preset);
    lua_getfield(L, cam, "position");
    if (lua_istable(L, -1)) {
      const Vec3 p = read_vector(L, -1, "camera position", 3);
      lua_getfield(L, cam, "target");
      const Vec3 t = read_vector(L, -1, "camera target", 3);
      lua_pop(L, 1);
      for (int a = 0; a < 3; ++a) f.camera_position[a] = p[a], f.camera_target[a] = t[a];
      f.camera_explicit = true;
    }
    lua_pop(L, 1);
    lua_getfield(L, cam, "up");
    if (lua_istable(L, -1)) {
      const Vec3 u = read_vector(L, -1, "camera up", 3);
      for (int a = 0; a < 3; ++a) f.camera_up[a] = u[a];
    }
    lua_pop(L, 1);
    f.camera_fov = read_number(L, cam, "fov", "camera", false, f.camera_fov);
    lua_getfield(L, cam, "region");
    if (!lua_isnil(L, -1)) read_camera_region(L, lua_gettop(L), f);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return 0;
}

int set_callback(lua_State* L, bool frame) {
  luaL_checktype(L, 1, LUA_TFUNCTION);
  auto* b = binding(L);
  int& ref = frame ? b->on_frame_ref : b->on_step_ref;
  if (ref != LUA_NOREF) luaL_unref(L, LUA_REGISTRYINDEX, ref);
  lua_pushvalue(L, 1);
  ref = luaL_ref(L, LUA_REGISTRYINDEX);
  return 0;
}
int l_on_step(lua_State* L) { return set_callback(L, false); }
int l_on_frame(lua_State* L) { return set_callback(L, true); }

int l_stop(lua_State* L) {
  auto* b = binding(L);
  b->stop_requested = true;
  b->stop_reason = luaL_optstring(L, 1, "stopped by the scene");
  return 0;
}

// Runs the scene's Lua callbacks from the run loop.
class LuaCallbacks final : public RunObserver {
 public:
  explicit LuaCallbacks(LuaScene::Binding* b) : b_(b) {}
  bool on_step(const Simulation& sim, const StepReport& r) override {
    return call(b_->on_step_ref, sim, &r, -1);
  }
  bool on_frame(const Simulation& sim, std::size_t frame) override {
    return call(b_->on_frame_ref, sim, nullptr, static_cast<long>(frame));
  }
  std::string stop_reason() const override { return b_->stop_reason; }

 private:
  bool call(int ref, const Simulation& sim, const StepReport* r, long frame) {
    if (ref == LUA_NOREF) return true;
    lua_State* L = b_->L;
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
    lua_newtable(L);
    lua_pushnumber(L, sim.time());
    lua_setfield(L, -2, "time");
    lua_pushinteger(L, sim.step_count());
    lua_setfield(L, -2, "step");
    if (r) {
      lua_pushnumber(L, r->dt);
      lua_setfield(L, -2, "dt");
      lua_pushinteger(L, r->ppe_iterations);
      lua_setfield(L, -2, "ppe_iterations");
      lua_pushnumber(L, r->max_speed);
      lua_setfield(L, -2, "max_speed");
      lua_pushnumber(L, r->kinetic_energy);
      lua_setfield(L, -2, "kinetic_energy");
    }
    if (frame >= 0) {
      lua_pushinteger(L, frame);
      lua_setfield(L, -2, "frame");
    }
    lua_newtable(L);
    const auto& probes = sim.model().probes;
    for (std::size_t k = 0; k < probes.size(); ++k) {
      lua_pushnumber(L, sim.probe_values()[k]);
      lua_setfield(L, -2, probes[k].name.c_str());
    }
    lua_setfield(L, -2, "probes");
    push_body_states(L, sim);
    lua_setfield(L, -2, "bodies");
    const char* name = frame >= 0 ? "on_frame" : "on_step";
    const int status = protected_call(L, 1, 1);
    if (status != LUA_OK)
      throw SceneError(std::string("the scene's ") + name + " callback failed at t = " +
                       number_text(sim.time()) + ": " + pop_error(L, status));
    // Nothing is read from a callback's result: anything but nil is a misunderstanding.
    const bool returned_nothing = lua_isnil(L, -1);
    lua_pop(L, 1);
    if (!returned_nothing)
      throw SceneError(std::string("the scene's ") + name +
                       " callback must return nothing (end the run with washout.stop(reason))");
    return !b_->stop_requested;
  }
  LuaScene::Binding* b_;
};

}  // namespace

LuaScene::LuaScene(const std::string& path, const Overrides& overrides,
                   const LuaLimitSettings& limits)
    : limits_(std::make_unique<LuaLimits>()), binding_(std::make_unique<Binding>()) {
  std::ifstream file(path);
  if (!file) throw SceneError("cannot read scene file '" + path + "'", path);
  std::stringstream source;
  source << file.rdbuf();
  model_.scene_path = path;
  model_.scene_source = source.str();
  model_.scene_name = std::filesystem::path(path).stem().string();

  limits_->settings = limits;
  L_ = new_limited_state(*limits_);
  if (!L_) throw SceneError("cannot start Lua (out of memory)", path);
  luaL_openlibs(L_);
  binding_->scene = this;
  binding_->L = L_;
  binding_->overrides = overrides;

  // require() finds the shared helpers in scripts/ and modules beside the scene.
  const char* env_scripts = std::getenv("WASHOUT_SCRIPTS");
  const std::string scripts = env_scripts ? env_scripts : WASHOUT_SCRIPTS_DIR;
  const std::string scene_dir = std::filesystem::path(path).parent_path().string();
  lua_getglobal(L_, "package");
  lua_getfield(L_, -1, "path");
  const std::string lua_path = scripts + "/?.lua;" + (scene_dir.empty() ? "." : scene_dir) +
                               "/?.lua;" + lua_tostring(L_, -1);
  lua_pop(L_, 1);
  lua_pushstring(L_, lua_path.c_str());
  lua_setfield(L_, -2, "path");
  lua_pop(L_, 1);

  static const luaL_Reg functions[] = {{"parameters", l_parameters},
                                       {"box", l_box},
                                       {"cylinder", l_cylinder},
                                       {"sphere", l_sphere},
                                       {"union", l_union},
                                       {"fluid", l_fluid},
                                       {"wall", l_wall},
                                       {"moving_wall", l_moving_wall},
                                       {"probe", l_probe},
                                       {"output", l_output},
                                       {"frames", l_frames},
                                       {"on_step", l_on_step},
                                       {"on_frame", l_on_frame},
                                       {"stop", l_stop},
                                       {"body", l_body},
                                       {"material", l_material},
                                       {"friction", l_friction},
                                       {"contact", l_contact},
                                       {nullptr, nullptr}};
  lua_newtable(L_);
  lua_pushlightuserdata(L_, binding_.get());
  luaL_setfuncs(L_, functions, 1);
  lua_pushstring(L_, WASHOUT_VERSION);
  lua_setfield(L_, -2, "version");
  validation_.install(L_);
  lua_setglobal(L_, "washout");

  try {
    int status = LUA_OK;
    auto run_protected = [&](lua_CFunction f) {
      if (f == nullptr)
        return luaL_loadfile(L_, path.c_str()) == LUA_OK &&
               (status = protected_call(L_, 0, 0)) == LUA_OK;
      lua_pushlightuserdata(L_, binding_.get());
      lua_pushcclosure(L_, f, 1);
      return (status = protected_call(L_, 0, 0)) == LUA_OK;
    };
    // The script, then (if it never called washout.parameters) the defaults with the overrides.
    const bool ok = run_protected(nullptr) &&
                    (binding_->resolved || run_protected([](lua_State* Ls) {
                       auto* b = static_cast<Binding*>(lua_touserdata(Ls, lua_upvalueindex(1)));
                       b->resolve(Ls, 0);
                       return 0;
                     }));
    if (!ok) {
      if (binding_->pending) throw SceneError(*binding_->pending);
      throw SceneError(pop_error(L_, status), path);
    }
    check_probes(model_);
    check_particle_budget(model_);
  } catch (...) {
    lua_close(L_);
    L_ = nullptr;
    throw;
  }
  if (model_.output.file_name.empty()) model_.output.file_name = model_.scene_name + ".h5";
  callbacks_ = std::make_unique<LuaCallbacks>(binding_.get());
}

LuaScene::~LuaScene() {
  callbacks_.reset();
  if (L_) lua_close(L_);
}

RunObserver* LuaScene::callbacks() {
  const bool any = binding_->on_step_ref != LUA_NOREF || binding_->on_frame_ref != LUA_NOREF;
  return any ? callbacks_.get() : nullptr;
}

}  // namespace washout::lua
