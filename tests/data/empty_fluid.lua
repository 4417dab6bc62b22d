local P = washout.parameters { dim = 2, d0 = 0.01 }
washout.wall { washout.box { min = { 0, -0.03 }, max = { 1, 0 } }, name = "floor" }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.004, 0.004 } } }
