-- The wash-out experiment of METHOD.md section 4 as a 2D vertical section along the flume's
-- centreline (x along the flume, y vertical): a water column released by a gate lifted at
-- free-fall speed runs down a dry channel and washes a PLA girder model off its pier.
-- Dimensions, materials and which numbers come from the paper: scripts/flume.lua and
-- docs/girder_washout.md. In 2D the pier is a block across the whole section (no water passes
-- beside it) and masses and forces are per metre of span.
--   washout run scenes/girder_washout_2d.lua --set water_height=0.25   (0.25, 0.30, 0.35 m)
--   washout run scenes/girder_washout_2d.lua --set d0=0.005            (the paper's spacing)
-- tests/scene/test_girder_washout.cpp runs it at d0 = 0.01 m for two heights.
local flume = require("flume")

local P = washout.parameters {
  dim = 2,
  d0 = 0.01,              -- [assumption] default: well under a minute on two cores; paper: 0.005
  end_time = 2.0,         -- off the pier by 0.61-0.73 s, then carried 1.5-2 m down the channel;
                          -- the run stops early if the girder leaves the observation window
  output_interval = 0.02,
  scene = flume.defaults(),
}

local f = flume.build(P)
flume.probes(P, f)
flume.stop_when_girder_leaves(f)
-- Frames every 0.1 s of the reservoir and the observation window (the flume beyond it is
-- empty channel); still a wide picture, 4 m by 0.6 m.
washout.frames { width = 1920, height = 400, color = "speed", every = 5, range = { 0, 3 },
                 camera = { region = { min = { 0, 0 }, max = { f.window_x, P.wall_height } } } }
