-- A box of density 500 kg/m^3 in still water (2D). Archimedes: it floats at the draft
-- D = (rho_b / rho_w) H, half its height. Two checks (tests/scene/test_floating_box.cpp and
-- tests/scene/long_floating_box.cpp):
--   motion = "fixed":   held at the draft D, the fluid's pressure on it must carry its weight;
--   motion = "dynamic": released at start_draft, it must settle at D (heave period ~0.6 s).
-- The box is twice as wide as high: a square of half the water's density floats unstably
-- (metacentric height GM = B^2/(12 D) + D/2 - H/2 < 0 for B = H) and would roll onto a corner.
-- The scene scores itself (docs/validation.md): abs(time mean of the draft over the last
-- second - D) / D, the draft being the water level beside the box (the two probes' mean) less
-- the box's bottom, as tests/support/box_draft.hpp measures it.
local tank = require("tank")
local validation = require("validation")

local P = washout.parameters {
  dim = 2,
  d0 = 0.01,              -- box height / 10; the tests also run d0 = 0.005
  end_time = 3.0,
  output_interval = 0.05,
  scene = {
    box_width = 0.2,      -- B [m]
    box_height = 0.1,     -- H [m]
    box_density = 500,    -- rho_b [kg/m^3]
    start_draft = 0.03,   -- initial draft [m]; on lattice planes for d0 = 0.01 and 0.005
    water_depth = 0.2,    -- [m]
    tank_width = 0.6,     -- [m]
    motion = "dynamic",   -- or "fixed" (held at start_draft)
  },
}

local W, Hw = P.tank_width, P.water_depth
local B, H = P.box_width, P.box_height
local x0 = 0.5 * (W - B)
local bottom = Hw - P.start_draft
washout.fluid { washout.box { min = { 0, 0 }, max = { W, Hw } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { W, Hw + 2 * H } }), name = "tank" }
washout.body { washout.box { min = { x0, bottom }, max = { x0 + B, bottom + H } },
               name = "box", density = P.box_density, motion = P.motion }
-- The water level beside the box, halfway between it and each side wall.
washout.probe { name = "level_left", quantity = "water_height", at = { 0.5 * x0, 0 } }
washout.probe { name = "level_right", quantity = "water_height", at = { W - 0.5 * x0, 0 } }

local D = P.box_density / P.rho0 * H
washout.validation {
  name = "draft",
  metric = "abs(mean draft over the last 1 s - D) / D, draft = level beside the box - bottom",
  reference = "Archimedes, D = (rho_b / rho_w) H (analytic)",
  bound = 0.2,  -- one particle spacing of draft at d0 = 0.01 m (d0 / D), as the tests allow
  error = validation.time_mean {
    window = { math.max(0, P.end_time - 1), P.end_time }, reference = D, relative = true,
    series = function(run)
      local time, position = run.series("/bodies/box/time"), run.series("/bodies/box/position")
      local lt, lv = run.probe("level_left")
      local rt, rv = run.probe("level_right")
      local draft = {}
      for k = 1, #time do
        local level = 0.5 * (validation.interpolate(lt, lv, time[k]) +
                             validation.interpolate(rt, rv, time[k]))
        draft[k] = level - (position[k][2] - 0.5 * H)
      end
      return time, draft
    end,
  },
}
