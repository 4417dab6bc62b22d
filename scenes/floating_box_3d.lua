-- A box of density 500 kg/m^3 released in still water (3D). Archimedes: it settles at the draft
-- D = (rho_b / rho_w) H, half its height. tests/scene/long_floating_box.cpp compares the settled
-- draft, averaged over the last second, with D at d0 = 0.02 and 0.01 m.
-- The box is twice as wide as high in both horizontal directions (a square cross-section of
-- half the water's density would roll onto an edge: GM = B^2/(12 D) + D/2 - H/2 < 0 for B = H).
local tank = require("tank")

local P = washout.parameters {
  dim = 3,
  d0 = 0.02,              -- box height / 5; the long test runs d0 = 0.01
  end_time = 2.0,
  output_interval = 0.1,
  scene = {
    box_width = 0.2,      -- B, along x and y [m]
    box_height = 0.1,     -- H [m]
    box_density = 500,    -- rho_b [kg/m^3]
    start_draft = 0.04,   -- initial draft [m]; lattice-aligned for d0 = 0.02 and 0.01
    water_depth = 0.2,    -- [m]
    tank_width = 0.4,     -- along x and y [m]
  },
}

local W, Hw = P.tank_width, P.water_depth
local B, H = P.box_width, P.box_height
local x0 = 0.5 * (W - B)
local bottom = Hw - P.start_draft
washout.fluid { washout.box { min = { 0, 0, 0 }, max = { W, W, Hw } } }
washout.wall { tank.open_box(P, { min = { 0, 0, 0 }, max = { W, W, Hw + 2 * H } }), name = "tank" }
washout.body { washout.box { min = { x0, x0, bottom }, max = { x0 + B, x0 + B, bottom + H } },
               name = "box", density = P.box_density,
               angle_axis = "y" }
-- The water level beside the box, in a corner of the tank away from it.
washout.probe { name = "level", quantity = "water_height", at = { 0.5 * x0, 0.5 * x0, 0 } }
