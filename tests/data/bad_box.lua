local P = washout.parameters { dim = 2, d0 = 0.01 }
-- line 3: min above max
washout.fluid { washout.box { min = { 0, 1 }, max = { 1, 0 } } }
