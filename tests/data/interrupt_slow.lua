-- A run whose every step takes about 0.3 s of Lua (a busy on_step), for the double-signal test
-- in tests/reliability/test_interrupt.cpp: the second signal must not wait for the step.
local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.02, end_time = 100, output_interval = 0.001 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.1 } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.3, 0.2 } }), name = "tank" }
washout.on_step(function(s)
  local until_clock = os.clock() + 0.3
  while os.clock() < until_clock do end
end)
