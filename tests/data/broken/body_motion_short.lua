-- Broken on purpose (tests/data/broken/manifest.txt).
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.02, end_time = 0.02, output_interval = 0.01 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.1 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.3, 0.2 } }), name = "tank" }
washout.body { washout.box { min = { 0.2, 0.02 }, max = { 0.24, 0.06 } }, name = "block",
               density = 500, motion = function(t) return { 0 } end }
