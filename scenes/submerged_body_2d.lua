-- A fixed body held under still water (2D). The pressure integrated over its surface,
-- F_f = sum -P n dS, must equal the buoyancy rho0 g V (Archimedes) and its torque about the
-- centre of mass must vanish. tests/scene/test_body_submerged.cpp averages F_f over a window
-- and compares at two resolutions, for a box and for a disc (shape = "disc").
local tank = require("tank")

local P = washout.parameters {
  dim = 2,
  d0 = 0.01,
  end_time = 0.3,
  output_interval = 0.1,
  scene = {
    shape = "box",        -- "box" or "disc"
    size = 0.1,           -- box side or disc diameter [m]
    depth = 0.1,          -- water above the body's top [m]
    water_depth = 0.3,    -- [m]
    tank_width = 0.4,     -- [m]
  },
}

local W, Hw, S = P.tank_width, P.water_depth, P.size
local centre = { 0.5 * W, Hw - P.depth - 0.5 * S }
local shape
if P.shape == "disc" then
  shape = washout.cylinder { center = centre, radius = 0.5 * S }
else
  shape = washout.box { min = { centre[1] - 0.5 * S, centre[2] - 0.5 * S },
                        max = { centre[1] + 0.5 * S, centre[2] + 0.5 * S } }
end
washout.fluid { washout.box { min = { 0, 0 }, max = { W, Hw } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { W, 1.5 * Hw } }), name = "tank" }
washout.body { shape, name = "body", density = 2000, motion = "fixed" }
