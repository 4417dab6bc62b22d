-- Start-up of plane Poiseuille flow: fluid at rest between plates at y = 0 and y = L, periodic
-- along x, driven from t = 0 by a body force F along x (given as gravity). The velocity profile
-- is compared with the series solution (validation/reference/README.md) by
-- tests/scene/test_poiseuille.cpp. A viscous fluid keeps the time scale L^2/nu at 1 s.
local tank = require("tank")

local L = 0.1
local P = washout.parameters {
  dim = 2,
  d0 = L / 20,
  viscosity = 0.01,        -- nu [m^2/s]
  gravity = { 0.08, 0 },   -- the driving body force F [m/s^2]
  end_time = 1.0,
  output_interval = 0.1,
  wall_slip = 0.0,         -- no-slip plates
  periodic = "x",
  domain_min = { 0, -0.05 },
  domain_max = { 0.06, 0.15 },
  scene = { channel_width = L },
}

washout.fluid { washout.box { min = { 0, 0 }, max = { 0.06, P.channel_width } } }
washout.wall { tank.plates(P, 0, 0.06, 0, P.channel_width), name = "plates" }
