-- Broken on purpose (tests/data/broken/manifest.txt).
washout.parameters { d0 = -0.01 }
