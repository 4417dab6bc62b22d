-- A fluid block with a violent initial velocity and a tiny speed limit: must stop as unstable.
local P = washout.parameters { dim = 2, d0 = 0.01, end_time = 0.05, output_interval = 0.01,
                               max_speed = 0.5 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.1 } }, velocity = { 0, -0.2 } }
washout.wall { washout.box { min = { -0.03, -0.03 }, max = { 0.13, 0 } }, name = "floor" }
