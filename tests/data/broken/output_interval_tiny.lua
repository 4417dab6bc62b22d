-- Broken on purpose (tests/data/broken/manifest.txt): a frame every 1e-12 s, far below the
-- shortest adaptive step (dt_min); it once ended as "unstable at t = inf s".
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.02, end_time = 0.02, output_interval = 1e-12 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.1 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.3, 0.2 } }), name = "tank" }
