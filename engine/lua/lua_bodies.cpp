#include "engine/lua/lua_bodies.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <lua.hpp>
#include <string>

#include "engine/lua/lua_errors.hpp"
#include "engine/lua/lua_reading.hpp"
#include "engine/rigid/quaternion_integrator.hpp"
#include "engine/sim/rigid_body_system.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::lua {
namespace {

using namespace detail;

// A prescribed body motion from a Lua function t -> displacement {dx, dy[, dz]} of the centre
// of mass and, optionally, the rotation from the initial pose: an angle about z in 2D, a
// rotation vector {rx, ry, rz} (axis times angle) in 3D. The rates come from central
// differences over 2e-6 s (one-sided at t = 0), as for moving walls.
BodyMotion make_body_motion(lua_State* L, int ref, const std::string& name, int dim) {
  struct Pose {
    Vec3 displacement = Vec3::Zero(), rotation = Vec3::Zero();
  };
  auto call = [L, ref, name, dim](double t) {
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
    lua_pushnumber(L, t);
    const std::string what = "motion of body '" + name + "' at t = " + number_text(t);
    const int status = protected_call(L, 1, 2);
    if (status != LUA_OK) throw SceneError(what + " failed: " + pop_error(L, status));
    // Checked on every call: a displacement of dim numbers, then nothing, an angle about z
    // (2D) or a rotation vector of 3 numbers (3D), all finite.
    Pose pose;
    try {
      pose.displacement = returned_vector(L, -2, dim, what + ": the displacement");
      if (dim == 3 && !lua_isnil(L, -1)) {
        pose.rotation = returned_vector(L, -1, 3, what + ": the rotation vector");
      } else if (dim == 2 && !lua_isnil(L, -1)) {
        if (lua_type(L, -1) != LUA_TNUMBER)
          throw SceneError(what + ": the rotation must be an angle about z (a number), got a " +
                           luaL_typename(L, -1));
        pose.rotation.z() = lua_tonumber(L, -1);
        if (!std::isfinite(pose.rotation.z()))
          throw SceneError(what + ": the rotation must be finite, got " +
                           number_text(pose.rotation.z()));
      }
    } catch (...) {
      lua_pop(L, 2);
      throw;
    }
    lua_pop(L, 2);
    return pose;
  };
  return [call](double t) {
    const Pose now = call(t);
    const double delta = 1e-6;
    const double t0 = std::max(0.0, t - delta), t1 = t + delta;
    const Pose before = call(t0), after = call(t1);
    BodyPose pose;
    pose.displacement = now.displacement;
    pose.rotation = now.rotation;
    pose.velocity = (after.displacement - before.displacement) / (t1 - t0);
    const Eigen::AngleAxisd turn(
        rigid::quaternion_from_rotation_vector(after.rotation) *
        rigid::quaternion_from_rotation_vector(before.rotation).conjugate());
    pose.angular_velocity = turn.angle() / (t1 - t0) * turn.axis();
    return pose;
  };
}

Vec3 read_axis(lua_State* L, int index, int dim) {
  if (lua_type(L, index) == LUA_TSTRING) {
    const std::string axis = lua_tostring(L, index);
    if (axis != "x" && axis != "y" && axis != "z")
      fail(L, " washout.body: angle_axis must be \"x\", \"y\", \"z\" or a vector");
    return Vec3::Unit(axis[0] - 'x');
  }
  const Vec3 v = read_vector(L, index, "washout.body angle_axis", dim);
  if (!(v.norm() > 0.0)) fail(L, " washout.body: angle_axis must not be zero");
  return v.normalized();
}

void push_vector(lua_State* L, const Vec3& v, int dim) {
  lua_createtable(L, dim, 0);
  for (int a = 0; a < dim; ++a) {
    lua_pushnumber(L, v[a]);
    lua_seti(L, -2, a + 1);
  }
}

}  // namespace

bool material_defined(lua_State* L, const char* name) {
  const std::string n = name;
  if (n == "default") return true;
  for (const auto& m : resolved_model(L).materials)
    if (m.name == n) return true;
  return false;
}

int l_material(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.material", {"name", "E", "nu", "eps"});
  Model& model = resolved_model(L);
  MaterialSpec m;
  m.where = where(L);
  m.name = read_string(L, 1, "name", "");
  if (m.name.empty()) fail(L, " washout.material: missing 'name'");
  for (const auto& other : model.materials)
    if (other.name == m.name)
      fail(L, " washout.material: a material named '" + m.name + "' exists already (" +
                  other.where + ")");
  m.young_modulus = read_number(L, 1, "E", "washout.material", false, m.young_modulus);
  m.poisson_ratio = read_number(L, 1, "nu", "washout.material", false, m.poisson_ratio);
  m.restitution = read_number(L, 1, "eps", "washout.material", false, m.restitution);
  if (!(m.young_modulus > 0)) fail(L, " washout.material '" + m.name + "': E must be > 0 (Pa)");
  if (!(m.poisson_ratio >= 0 && m.poisson_ratio < 0.5))
    fail(L, " washout.material '" + m.name + "': nu must lie in [0, 0.5)");
  if (!(m.restitution > 0 && m.restitution <= 1))
    fail(L, " washout.material '" + m.name + "': eps must lie in (0, 1]");
  model.materials.push_back(m);
  lua_pushstring(L, m.name.c_str());
  return 1;
}

int l_friction(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.friction", {"mu", "eps"});
  Model& model = resolved_model(L);
  FrictionSpec f;
  f.where = where(L);
  std::string names[2];
  for (int k = 0; k < 2; ++k) {
    lua_geti(L, 1, k + 1);
    if (lua_type(L, -1) != LUA_TSTRING)
      fail(L,
           " washout.friction: give two material names first, e.g. "
           "washout.friction{ \"pla\", \"concrete\", 0.05 }");
    names[k] = lua_tostring(L, -1);
    lua_pop(L, 1);
    if (!material_defined(L, names[k].c_str()))
      fail(L, " washout.friction: unknown material '" + names[k] +
                  "' (define it with washout.material before)");
  }
  f.material_a = names[0];
  f.material_b = names[1];
  lua_geti(L, 1, 3);
  const bool positional = !lua_isnil(L, -1);
  if (positional && !lua_isnumber(L, -1)) fail(L, " washout.friction: mu must be a number");
  f.friction = positional ? lua_tonumber(L, -1) : 0.0;
  lua_pop(L, 1);
  lua_getfield(L, 1, "mu");
  const bool keyed = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (positional && keyed) fail(L, " washout.friction: give mu once (third entry or mu =)");
  if (keyed) f.friction = read_number(L, 1, "mu", "washout.friction", true, 0);
  f.restitution = read_number(L, 1, "eps", "washout.friction", false, -1.0);
  if (!positional && !keyed && f.restitution < 0)
    fail(L, " washout.friction: give mu (and optionally eps)");
  if (!(f.friction >= 0)) fail(L, " washout.friction: mu must be >= 0");
  if (f.restitution >= 0 && !(f.restitution > 0 && f.restitution <= 1))
    fail(L, " washout.friction: eps must lie in (0, 1]");
  model.frictions.push_back(f);
  return 0;
}

int l_contact(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(
      L, 1, "washout.contact",
      {"law", "damping_mass", "allow_tension", "steps_per_contact", "max_substeps", "rest_steps"});
  ContactSpec& c = resolved_model(L).contact;
  c.law = read_string(L, 1, "law", c.law);
  if (c.law != "linear" && c.law != "hertz")
    fail(L, " washout.contact: law must be \"linear\" or \"hertz\", got \"" + c.law + "\"");
  c.damping_mass = read_string(L, 1, "damping_mass", c.damping_mass);
  if (c.damping_mass != "shared" && c.damping_mass != "whole_body")
    fail(L, " washout.contact: damping_mass must be \"shared\" or \"whole_body\", got \"" +
                c.damping_mass + "\"");
  lua_getfield(L, 1, "allow_tension");
  if (!lua_isnil(L, -1)) {
    if (!lua_isboolean(L, -1)) fail(L, " washout.contact: allow_tension must be true or false");
    c.allow_tension = lua_toboolean(L, -1) != 0;
  }
  lua_pop(L, 1);
  c.steps_per_contact =
      read_number(L, 1, "steps_per_contact", "washout.contact", false, c.steps_per_contact);
  if (!(c.steps_per_contact >= 1)) fail(L, " washout.contact: steps_per_contact must be >= 1");
  const double most =
      read_number(L, 1, "max_substeps", "washout.contact", false, double(c.max_substeps));
  if (!(most >= 1)) fail(L, " washout.contact: max_substeps must be >= 1");
  c.max_substeps = static_cast<long>(most);
  const double rest =
      read_number(L, 1, "rest_steps", "washout.contact", false, double(c.rest_steps));
  if (!(rest >= 0 && rest <= 1e9 && rest == std::floor(rest)))
    fail(L, " washout.contact: rest_steps must be a whole number >= 0 (0: bodies never sleep)");
  c.rest_steps = static_cast<int>(rest);
  return 0;
}

int l_body(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  check_keys(L, 1, "washout.body",
             {"shape", "name", "density", "mass", "material", "motion", "velocity",
              "angular_velocity", "angle_axis", "slip"});
  Model& model = resolved_model(L);
  const int dim = model.params.dim;
  BodySpec body;
  body.where = where(L);
  body.shape = region_shape(L, "washout.body", dim);
  body.name = read_string(L, 1, "name", "body_" + std::to_string(model.bodies.size()));
  if (body.name.empty() || body.name.find('/') != std::string::npos || body.name == "." ||
      body.name == "..")
    fail(L, " washout.body: name must be a non-empty word without '/' (it names /bodies/NAME)");
  for (const auto& other : model.bodies)
    if (other.name == body.name)
      fail(L,
           " washout.body: a body named '" + body.name + "' exists already (" + other.where + ")");
  const std::string what = "washout.body '" + body.name + "'";
  body.density = read_number(L, 1, "density", what.c_str(), false, 0.0);
  body.mass = read_number(L, 1, "mass", what.c_str(), false, 0.0);
  if ((body.density > 0) == (body.mass > 0) || body.density < 0 || body.mass < 0)
    fail(L, " " + what + ": give a positive density (kg/m^" + std::to_string(dim) +
                ") or a positive mass (kg" + (dim == 2 ? " per metre of thickness" : "") +
                "), not both");
  body.material = read_string(L, 1, "material", "");
  if (!body.material.empty() && !material_defined(L, body.material.c_str()))
    fail(L, " " + what + ": unknown material '" + body.material +
                "' (define it with washout.material before)");
  body.slip = read_number(L, 1, "slip", what.c_str(), false, model.params.wall_slip);
  if (!(body.slip >= 0 && body.slip <= 1)) fail(L, " " + what + ": slip must lie in [0, 1]");

  lua_getfield(L, 1, "motion");
  if (lua_isfunction(L, -1)) {
    body.motion = BodySpec::Motion::Prescribed;
    const int ref = luaL_ref(L, LUA_REGISTRYINDEX);
    body.prescribed = make_body_motion(L, ref, body.name, dim);
  } else {
    const std::string motion = lua_isnil(L, -1)                 ? "dynamic"
                               : lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1)
                                                                : "";
    lua_pop(L, 1);
    if (motion == "dynamic")
      body.motion = BodySpec::Motion::Dynamic;
    else if (motion == "fixed")
      body.motion = BodySpec::Motion::Fixed;
    else
      fail(L, " " + what + ": motion must be \"dynamic\", \"fixed\" or a function of time");
  }
  lua_getfield(L, 1, "velocity");
  if (!lua_isnil(L, -1)) body.velocity = read_vector(L, -1, "washout.body velocity", dim);
  lua_pop(L, 1);
  lua_getfield(L, 1, "angular_velocity");
  if (dim == 2 && !lua_isnil(L, -1)) {
    if (!lua_isnumber(L, -1))
      fail(L, " " + what + ": angular_velocity in 2D is a number (rad/s about z)");
    body.angular_velocity = Vec3(0, 0, lua_tonumber(L, -1));
  } else if (!lua_isnil(L, -1)) {
    body.angular_velocity = read_vector(L, -1, "washout.body angular_velocity", dim);
  }
  lua_pop(L, 1);
  if ((body.motion != BodySpec::Motion::Dynamic) &&
      (body.velocity.norm() > 0 || body.angular_velocity.norm() > 0))
    fail(L, " " + what + ": velocity and angular_velocity are for dynamic bodies");
  // The reported rotation angle: about z in 2D; in 3D about y by default (the vertical plane
  // x-z of a flow along x).
  body.angle_axis = dim == 2 ? Vec3::UnitZ() : Vec3::UnitY();
  lua_getfield(L, 1, "angle_axis");
  if (!lua_isnil(L, -1)) {
    body.angle_axis = read_axis(L, lua_gettop(L), dim);
    if (dim == 2 && body.angle_axis != Vec3::UnitZ())
      fail(L, " " + what + ": in 2D bodies turn about z only (angle_axis = \"z\")");
  }
  lua_pop(L, 1);
  model.bodies.push_back(std::move(body));
  return 0;
}

void push_body_states(lua_State* L, const Simulation& sim) {
  lua_newtable(L);
  const RigidBodySystem* bodies = sim.bodies();
  if (!bodies) return;
  const int dim = sim.params().dim;
  for (std::size_t b = 0; b < bodies->size(); ++b) {
    const rigid::BodyState& s = bodies->state(b);
    lua_newtable(L);
    push_vector(L, s.position, dim);
    lua_setfield(L, -2, "position");
    push_vector(L, s.velocity, dim);
    lua_setfield(L, -2, "velocity");
    if (dim == 2)
      lua_pushnumber(L, s.angular_velocity.z());
    else
      push_vector(L, s.angular_velocity, 3);
    lua_setfield(L, -2, "angular_velocity");
    const Eigen::Quaterniond& q = s.orientation;
    push_vector(L, Vec3(q.w(), q.x(), q.y()), 3);
    lua_pushnumber(L, q.z());
    lua_seti(L, -2, 4);
    lua_setfield(L, -2, "quaternion");
    lua_pushnumber(L, bodies->angle(b));
    lua_setfield(L, -2, "angle");
    push_vector(L, bodies->fluid_load(b).force, dim);
    lua_setfield(L, -2, "force_fluid");
    push_vector(L, bodies->contact_load(b).force, dim);
    lua_setfield(L, -2, "force_contact");
    lua_setfield(L, -2, bodies->name(b).c_str());
  }
}

}  // namespace washout::lua
