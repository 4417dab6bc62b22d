-- Dam break of Martin & Moyce (1952), n^2 = 2, extruded in a narrow 3D tank (width a/2), the
-- 3D counterpart of dambreak_2d.lua. It scores itself as the 2D scene does: RMS of the front
-- Z = x/a against T = t sqrt(2 g / a) minus Martin & Moyce's Table 2 over T <= 3
-- (validation/reference/mm1952_n2_front_table.csv; docs/validation.md).
local tank = require("tank")
local validation = require("validation")

local a = 0.146
local P = washout.parameters {
  dim = 3,
  d0 = a / 20,
  end_time = 0.3,          -- T = 3.5
  output_interval = 0.01,
  scene = {
    column_width = a,
    column_height = 2 * a,
    tank_length = 5 * a,
    tank_width = a / 2,    -- 0.073 m: the narrow tank of the issue
    tank_height = 3 * a,
  },
}

washout.fluid { washout.box { min = { 0, 0, 0 },
                              max = { P.column_width, P.tank_width, P.column_height } } }
washout.wall { tank.open_box(P, { min = { 0, 0, 0 },
                                  max = { P.tank_length, P.tank_width, P.tank_height } }),
               name = "tank" }
washout.probe { name = "front", quantity = "front", axis = "x" }
-- The column's height at the back wall, mid-width (Martin & Moyce's residual height).
washout.probe { name = "residual_height", quantity = "water_height",
                at = { 0.5 * P.d0, 0.5 * P.tank_width, 0 } }
-- Bound: a regression bound, what the engine reaches at a/d0 = 10 and 20 with a margin
-- (docs/validation.md); the error does not fall with d0, the surge's speed after the release
-- does (front_speed, bound 0.25; docs/method.md, the twenty-second and twenty-third sessions).
validation.martin_moyce_front(P, P.column_width, 0.25, "residual_height", 0.25)
