-- Valid, but not base.lua: a run of base.lua cannot be continued with it (--restart,
-- tests/data/broken/manifest.txt). The water is 0.12 m deep instead of 0.1 m.
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.02, end_time = 0.02, output_interval = 0.01 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.12 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.3, 0.2 } }), name = "tank" }
