-- A run with a body whose on_step callback fails after 0.05 s, for
-- tests/reliability/test_interrupt.cpp: the run ends with exit 1, and the steps before the
-- error keep their body report (block.csv) and their rows in the run file.
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.02, end_time = 1, output_interval = 0.02 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.3, 0.1 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.3, 0.3 } }), name = "tank" }
washout.body { washout.box { min = { 0.1, 0.08 }, max = { 0.16, 0.12 } }, name = "block",
               density = 500 }
washout.on_step(function(s)
  if s.time > 0.05 then error("the scene's own check failed") end
end)
