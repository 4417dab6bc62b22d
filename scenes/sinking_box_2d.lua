-- A heavy box sinks in still water, lands on the floor and comes to rest on it without passing
-- through (2D). Contact is the DEM spring-dashpot of METHOD.md ("Contact") between the box and
-- the tank, sub-stepped inside each fluid step (/stats/substeps). At rest the contact and fluid
-- loads carry the weight, F_c + F_f = M g, and the box's bottom sits on the floor less the
-- static overlap of the contact springs (about 3e-8 m). With no water left under the box the
-- fluid presses it down (F_f < 0): there is no buoyancy without pressure under the bottom.
-- tests/scene/test_body_sinking.cpp checks this at two resolutions; --set drop=0 starts the box
-- resting on the floor.
--
-- Particle shifting (docs/method.md) is on: as the gap under the box closes, its water has to
-- lose rows of particles, and without shifting it leaves holes there. At d0 = 0.005 m the
-- water then burst out at the box's feet at 1-2.5 m/s and stopped the run as unstable, before
-- or soon after landing, in every variant tried without it (docs/bodies.md, "Sinking box").
local tank = require("tank")

local P = washout.parameters {
  dim = 2,
  d0 = 0.005,
  end_time = 1.5,
  output_interval = 0.05,
  shifting = 0.5,
  scene = {
    box_width = 0.08,     -- [m]
    box_height = 0.04,    -- [m]
    box_density = 2000,   -- [kg/m^3]
    drop = 0.06,          -- initial gap between the box and the floor [m]
    water_depth = 0.2,    -- [m]
    tank_width = 0.3,     -- [m]
  },
}

local W, Hw, B, H = P.tank_width, P.water_depth, P.box_width, P.box_height
local x0 = 0.5 * (W - B)
local concrete = washout.material { name = "concrete", E = 3.0e10, nu = 0.2, eps = 0.5 }
local pla = washout.material { name = "pla", E = 5.0e9, nu = 0.28, eps = 0.5 }
washout.friction { pla, concrete, 0.3 }
washout.fluid { washout.box { min = { 0, 0 }, max = { W, Hw } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { W, 1.5 * Hw } }), name = "tank",
               material = concrete }
washout.body { washout.box { min = { x0, P.drop }, max = { x0 + B, P.drop + H } },
               name = "box", density = P.box_density, material = pla }
