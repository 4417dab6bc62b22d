-- Broken on purpose (tests/data/broken/manifest.txt).
washout.parameters { dim = 2 }
