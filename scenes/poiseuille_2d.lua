-- Start-up of plane Poiseuille flow: fluid at rest between plates at y = 0 and y = L, periodic
-- along x, driven from t = 0 by a body force F along x (given as gravity). The velocity profile
-- is compared with the series solution by tests/scene/test_poiseuille.cpp, and the scene scores
-- itself the same way (docs/validation.md): relative L2 error of u_x over the fluid at t = 0.2 s
-- (primary) and at the end. A viscous fluid keeps the time scale L^2/nu at 1 s.
local tank = require("tank")
local validation = require("validation")

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

-- u(y, t) = F/(2 nu) y (L - y) - sum_n 4 F L^2 / (nu pi^3 k^3) sin(k pi y / L) exp(-k^2 pi^2 nu t / L^2),
-- k = 2n + 1: the start-up from rest (docs/validation.md).
local F, nu, W = P.gravity[1], P.viscosity, P.channel_width
local function exact(y, t)
  local u = F / (2 * nu) * y * (W - y)
  for n = 0, 199 do
    local k = 2 * n + 1
    u = u - 4 * F * W * W / (nu * math.pi ^ 3 * k ^ 3) * math.sin(k * math.pi * y / W) *
            math.exp(-k * k * math.pi * math.pi * nu * t / (W * W))
  end
  return u
end
local function score(name, time, bound)
  washout.validation {
    name = name, bound = bound,
    metric = string.format("relative L2 of u_x over the fluid at t = %g s", time),
    reference = "plane Poiseuille start-up, series solution (analytic)",
    error = validation.profile_l2 {
      time = time, field = "velocity", component = 1,
      reference = function(x, t) return exact(x[2], t) end,
    },
  }
end
-- Bounds: the test's (measured 0.66 % and 2.2 % at L/d0 = 20, with about 50 % margin).
score("profile_early", 0.2, 0.01)
score("profile_end", P.end_time, 0.033)
