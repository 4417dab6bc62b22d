-- Broken on purpose (tests/data/broken/manifest.txt): a count of fluid steps must be whole.
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.02, end_time = 0.02, output_interval = 0.01 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.1 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.3, 0.2 } }), name = "tank" }
washout.contact { rest_steps = 2.5 }
