-- A long run with a floating body, for tests/reliability/test_interrupt.cpp: it is stopped by
-- SIGTERM long before end_time.
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.01, end_time = 100, output_interval = 0.05 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.3, 0.1 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.3, 0.3 } }), name = "tank" }
washout.body { washout.box { min = { 0.1, 0.08 }, max = { 0.16, 0.12 } }, name = "block",
               density = 500 }
