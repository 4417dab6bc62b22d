-- The wash-out experiment of METHOD.md section 4 in 3D (x along the flume, y across, z up): a
-- water column released by a gate lifted at free-fall speed runs down a dry glass flume and
-- washes a PLA girder model, spanning the flume wall to wall, off its pier. Dimensions,
-- materials and which numbers come from the paper: scripts/flume.lua and
-- docs/girder_washout.md. The run writes /bodies/girder, girder.csv and the summary
-- (docs/output.md); scripts/plot_washout.py draws it.
--   washout run scenes/girder_washout.lua --set water_height=0.25   (0.25, 0.30, 0.35 m)
--   washout run scenes/girder_washout.lua --set d0=0.005            (the paper's spacing)
local flume = require("flume")

local P = washout.parameters {
  dim = 3,
  d0 = 0.02,              -- [assumption] default: about two minutes on two cores; paper: 0.005
  end_time = 1.5,         -- the girder is off the pier by about 0.85 s and 0.8 m downstream at
                          -- 1.5 s; the run also stops when it leaves the observation window
  output_interval = 0.05,
  scene = flume.defaults(),
}

local f = flume.build(P)
flume.probes(P, f)
flume.stop_when_girder_leaves(f)
-- Frames every 0.1 s of the reservoir, the gate and the pier, from the -y side and above (the
-- near side wall is cut away, docs/render.md).
washout.frames {
  width = 1280, height = 720, color = "speed", every = 2, range = { 0, 3 },
  camera = { position = { 1.3, -2.2, 1.0 }, target = { 1.3, 0.24, 0.12 }, fov = 35 },
}
