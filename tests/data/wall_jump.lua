-- A plate that jumps 2 cm (two spacings, inside the kernel's reach of 2.4 cm, so every particle
-- it lands on sees it) into a water column in one step, its motion teleporting it and saying it
-- is at rest: two columns of fluid particles (20) are found inside it at once, and the crossing
-- guard (docs/stability.md) stops the run instead of pushing them all back out unseen.
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.01, end_time = 0.1, output_interval = 0.01 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.2, 0.1 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.5, 0.3 } }), name = "tank" }
washout.moving_wall {
  washout.box { min = { 0.2, 0 }, max = { 0.23, 0.3 } }, name = "plate",
  motion = function(t)
    if t < 0.02 then return { 0, 0 }, { 0, 0 } end
    return { -0.02, 0 }, { 0, 0 }
  end,
}
