-- A water column held by a gate lifted at free-fall speed (z = g t^2 / 2): one line of Lua.
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.01, end_time = 0.25, output_interval = 0.05 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.2 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.5, 0.3 } }), name = "tank" }
washout.moving_wall { washout.box { min = { 0.1, 0 }, max = { 0.13, 0.3 } }, name = "gate",
                      motion = function(t) return { 0, 0.5 * 9.81 * t * t } end }
washout.probe { name = "front", quantity = "front", axis = "x" }
