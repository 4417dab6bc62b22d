-- Broken on purpose (tests/data/broken/manifest.txt).
local P = washout.parameters { dim = 2, d0 = 0.02, dim = 4 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.1, 0.1 } } }
