#pragma once
// The Lua functions for rigid bodies and contact (docs/bodies.md): washout.body,
// washout.material, washout.friction, washout.contact; and the body states handed to the
// scene's callbacks (state.bodies.NAME).
struct lua_State;

namespace washout {
class Simulation;
}

namespace washout::lua {

// Each expects the scene binding as its first upvalue (registered with the other washout.*).
int l_body(lua_State* L);
int l_material(lua_State* L);
int l_friction(lua_State* L);
int l_contact(lua_State* L);

// Whether a wall or body may name this contact material: "default", or one defined already.
bool material_defined(lua_State* L, const char* name);

// Pushes the table of body states: {NAME = {position, velocity, angular_velocity, quaternion,
// angle, force_fluid, force_contact}, ...}; empty when the scene has no bodies.
void push_body_states(lua_State* L, const Simulation& sim);

}  // namespace washout::lua
