-- A violent case of the stability suite (docs/stability.md): a heavy box dropped from 0.5 m
-- above still water hits it at about 3 m/s, sinks and lands on the floor (2D). What it checks is
-- that the run either stays physical (the box comes to rest on the floor, the splash falls
-- back) or stops with a guard's message; the loads at impact are reported, not validated.
--   washout run scenes/stability/box_drop_2d.lua                 (d0 = 0.01 m, 1.5 s)
--   washout run scenes/stability/box_drop_2d.lua --set drop_height=0.25 --set box_density=500
local tank = require("tank")

local P = washout.parameters {
  dim = 2,
  d0 = 0.01,
  end_time = 1.5,
  output_interval = 0.05,
  shifting = 0.5,  -- as the sinking box: the closing gap under the box must lose rows of particles
  scene = {
    box_width = 0.08,     -- [m]
    box_height = 0.04,    -- [m]
    box_density = 2000,   -- [kg/m^3]
    drop_height = 0.5,    -- from the water surface to the box's bottom at release [m]
    water_depth = 0.2,    -- [m]
    tank_width = 0.4,     -- [m]
  },
}

for _, name in ipairs { "box_width", "box_height", "box_density", "water_depth", "tank_width" } do
  if not (type(P[name]) == "number" and P[name] > 0) then
    error(("box_drop_2d: %s must be a positive number"):format(name), 0)
  end
end
if not (P.drop_height >= 0) then error("box_drop_2d: drop_height must be >= 0", 0) end

local W, D, B, H = P.tank_width, P.water_depth, P.box_width, P.box_height
local x0 = 0.5 * (W - B)
local top = D + P.drop_height + H + 0.1  -- the walls stand above the box at release
local concrete = washout.material { name = "concrete", E = 3.0e10, nu = 0.2, eps = 0.5 }
local pla = washout.material { name = "pla", E = 5.0e9, nu = 0.28, eps = 0.5 }
washout.friction { pla, concrete, 0.3 }
washout.fluid { washout.box { min = { 0, 0 }, max = { W, D } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { W, top } }), name = "tank",
               material = concrete }
local y0 = D + P.drop_height
washout.body { washout.box { min = { x0, y0 }, max = { x0 + B, y0 + H } },
               name = "box", density = P.box_density, material = pla }
