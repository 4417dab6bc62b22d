local P = washout.parameters { dim = 2, d0 = 0.01 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.1 } } }
-- line 4: the region's max lies left of its min
washout.frames { camera = { region = { min = { 0.5, 0 }, max = { 0.2, 0.6 } } } }
