-- Water at rest in a tank (2D). The pressure must settle to rho g (H - y) with no particle
-- crossing a wall. Used to calibrate alpha and to test the wall treatment. The scene scores
-- itself against rho g (H - y) and the water's weight (docs/validation.md).
local tank = require("tank")
local validation = require("validation")

local P = washout.parameters {
  dim = 2,
  d0 = 0.005,            -- 20 particles over the depth
  end_time = 1.0,
  output_interval = 0.1,
  wall_slip = 0.0,
  scene = {
    water_height = 0.1,  -- H [m]
    tank_width = 0.1,    -- [m]
  },
}

local W, H = P.tank_width, P.water_height
washout.fluid { washout.box { min = { 0, 0 }, max = { W, H } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { W, 1.5 * H } }), name = "tank" }
washout.probe { name = "bottom_pressure", quantity = "pressure", at = { W / 2, 0.1 * H } }
-- Bounds: P = 0 is imposed at the surface (docs/method.md); measured after 0.5 s at d0 = H/10,
-- H/20, H/40: pressure 0.45 %, 0.27 %, 0.18 %, floor force the same. 0.6 % leaves a margin.
validation.hydrostatic(P, H, { 0, W }, { pressure = 0.006, floor_force = 0.006 })
