-- The wash-out flume of METHOD.md section 4 ("The validation experiment"): a reservoir closed
-- by a gate lifted at free-fall speed, a dry channel downstream, a fixed pier and a girder
-- model resting on it. Loaded by scenes/girder_washout.lua (3D) and
-- scenes/girder_washout_2d.lua (a vertical section along the flume's centreline) with
-- `local flume = require("flume")`.
--
-- Coordinates: x along the flume (flow towards +x), the last axis vertical (y in 2D, z in 3D),
-- y across the flume in 3D. x = 0 is the reservoir's back wall, the floor's top is at 0.
--
-- The paper gives the water heights, the girder's material, the contact and wall parameters and
-- the particle spacing with its particle counts; its figures with the flume and girder
-- dimensions are not available to us. Every dimension below says which it is:
--   [paper]       METHOD.md section 4;
--   [assumption]  ours: a realistic laboratory flume and a girder model at about 1/40 scale,
--                 sized so that d0 = 5 mm gives the paper's 2.4 / 2.6 / 2.7 million particles.
--
-- Particle count at d0 = 0.005 m in 3D, as built by the engine (fluid + walls, gate, pier and
-- girder), from `washout run scenes/girder_washout.lua --set d0=0.005 --set water_height=H`:
--   H = 0.25 m: 748,800 + 1,686,420 = 2,435,220    (paper: about 2.4 million)
--   H = 0.30 m: 898,560 + 1,686,420 = 2,584,980    (paper: about 2.6 million)
--   H = 0.35 m: 1,048,320 + 1,686,420 = 2,734,740  (paper: about 2.7 million)
-- By volumes: the fluid is L_res W H / d0^3 = 0.78 x 0.48 x H / 1.25e-7 (149,760 per 50 mm of
-- water: the paper's counts rise by 0.1 to 0.2 million per 50 mm, which fixes L_res W at about
-- 0.37 m^2); the walls are three particle layers (ceil(2h/d0), h = 1.2 d0), 3 A / d0^2 for a
-- wall area A: the floor and the 0.6 m sides of the 7.5 m flume make most of the 1.69 million.

-- Lattice: particles sit on x = (i + 1/2) d0, so faces at whole multiples of d0 line up. Every
-- horizontal position and every height of the pier and the girder is a multiple of 0.06 m, so
-- that d0 = 0.005, 0.006, 0.0075, 0.01, 0.012, 0.015, 0.02, 0.03 (0.06 / k) all seat the girder
-- exactly on the pier; other values are refused (the girder would hang above the pier or
-- overlap it by a fraction of d0). The water height need not be a multiple of d0: the column
-- is filled up to it, so it is represented to within d0/2.
local tank = require("tank")

local flume = {}

-- The scene parameters of the experiment, for washout.parameters{ scene = flume.defaults() }.
-- A scene may change any of them, and a user any of them with --set NAME=VALUE.
function flume.defaults()
  return {
    water_height = 0.30,       -- [paper] initial water column: 0.25, 0.30 or 0.35 m
    reservoir_length = 0.78,   -- [assumption] back wall to gate, m (sets 150 k particles per 5 cm)
    flume_length = 7.50,       -- [assumption] back wall to downstream end wall, m
    flume_width = 0.48,        -- [assumption] between the glass side walls, m (3D only)
    wall_height = 0.60,        -- [assumption] side walls and gate, m
    pier_distance = 1.02,      -- [assumption] gate (x = reservoir_length) to pier's upstream face, m
    pier_length = 0.12,        -- [assumption] pier along the flow, m
    pier_width = 0.12,         -- [assumption] pier across the flume, m (3D; centred)
    pier_height = 0.06,        -- [assumption] floor to pier top (girder's bottom), m
    girder_width = 0.24,       -- [assumption] girder along the flow (the deck's width), m
    girder_height = 0.06,      -- [assumption] girder depth, m (width / depth = 4, a usual deck)
    girder_density = 1161,     -- [paper] PLA, kg/m^3 (3D: span = flume_width, wall to wall)
    gate_lift = 0.70,          -- [assumption] the gate stops once lifted this far, m (clear of the walls)
    gate_speed = 0,            -- [assumption] 0: the gate is lifted at free fall (g t^2 / 2); > 0:
                               -- at this constant speed, m/s (100: opened almost at once)
    girder_young_modulus = 5.0e9,  -- [paper] PLA's E, Pa (the stability suite sweeps it)
    girder_restitution = 0.8,      -- [paper] PLA's eps (the stability suite sweeps it)
    window_length = 2.10,      -- [assumption] observation window: the run stops when the girder's
                               -- centre is this far downstream of the pier's upstream face, m
  }
end

-- Contact, [paper]: E = 5.0e9 Pa, nu = 0.28, eps = 0.8 for the PLA girder; friction girder-pier
-- 0.05, girder-wall 0.0. The paper gives one (E, nu, eps); we give the pier and the flume's walls
-- the same values [assumption] and name them apart so that each pair has its friction. The
-- girder's E and eps are the scene parameters girder_young_modulus and girder_restitution.
flume.girder_material = { name = "pla", nu = 0.28 }
flume.pier_material = { name = "pier", E = 5.0e9, nu = 0.28, eps = 0.8 }
flume.wall_material = { name = "glass", E = 5.0e9, nu = 0.28, eps = 0.8 }
flume.mu_girder_pier = 0.05  -- [paper]
flume.mu_girder_wall = 0.0   -- [paper]

local lattice_unit = 0.06  -- every pier and girder dimension is a multiple of this (see above)

-- Is v a whole multiple of step (to 1e-9 relative)?
local function multiple_of(v, step)
  local k = v / step
  return math.abs(k - math.floor(k + 0.5)) < 1e-6
end

local function positive(P, name)
  local v = P[name]
  if type(v) ~= "number" or not (v > 0) then
    error(("flume: %s must be positive, got %s"):format(name, tostring(v)), 0)
  end
end

-- Refuses dimensions that cannot make the experiment, naming the parameter. The messages carry
-- no position: flume.build re-raises them at the scene's line.
function flume.check(P)
  for _, name in ipairs { "water_height", "reservoir_length", "flume_length", "wall_height",
                          "pier_distance", "pier_length", "pier_height", "girder_width",
                          "girder_height", "girder_density", "gate_lift", "window_length",
                          "girder_young_modulus", "girder_restitution" } do
    positive(P, name)
  end
  if type(P.gate_speed) ~= "number" or not (P.gate_speed >= 0) then
    error(("flume: gate_speed = %s must be a number >= 0 (0: free fall)"):format(
      tostring(P.gate_speed)), 0)
  end
  if P.dim == 3 then
    positive(P, "flume_width")
    positive(P, "pier_width")
  end
  if P.water_height >= P.wall_height then
    error(("flume: water_height = %g m must be below wall_height = %g m (the reservoir would "
           .. "overflow)"):format(P.water_height, P.wall_height), 0)
  end
  if P.water_height < 2 * P.d0 then
    error(("flume: water_height = %g m is less than two particles of d0 = %g m")
          :format(P.water_height, P.d0), 0)
  end
  local gate = tank.wall_thickness(P)
  if P.pier_distance < gate + P.d0 then
    error(("flume: pier_distance = %g m leaves no channel between the gate (%g m thick at "
           .. "d0 = %g m) and the pier"):format(P.pier_distance, gate, P.d0), 0)
  end
  local overhang = 0.5 * (P.girder_width - P.pier_length)
  if overhang < 0 then
    error(("flume: girder_width = %g m is narrower than pier_length = %g m: the girder must "
           .. "cover the pier's top"):format(P.girder_width, P.pier_length), 0)
  end
  local girder_end = P.reservoir_length + P.pier_distance + P.pier_length + overhang
  if girder_end + P.window_length > P.flume_length then
    error(("flume: flume_length = %g m ends inside the observation window (pier at %g m, "
           .. "window_length = %g m)"):format(P.flume_length,
                                             P.reservoir_length + P.pier_distance,
                                             P.window_length), 0)
  end
  if P.pier_height + P.girder_height >= P.wall_height then
    error(("flume: the girder's top (pier_height + girder_height = %g m) must be below "
           .. "wall_height = %g m"):format(P.pier_height + P.girder_height, P.wall_height), 0)
  end
  if P.dim == 3 and P.pier_width > P.flume_width then
    error(("flume: pier_width = %g m is wider than flume_width = %g m")
          :format(P.pier_width, P.flume_width), 0)
  end
  if P.gate_lift < P.wall_height then
    error(("flume: gate_lift = %g m must be at least wall_height = %g m, or the gate would stop "
           .. "in the flow"):format(P.gate_lift, P.wall_height), 0)
  end
  -- The girder sits on the pier only if both are built on lattice planes: every position and
  -- height of the pier and the girder must be a whole number of particles.
  local names = { "reservoir_length", "pier_distance", "pier_length", "pier_height",
                  "girder_width", "girder_height" }
  if P.dim == 3 then
    names[#names + 1] = "flume_width"
    names[#names + 1] = "pier_width"
  end
  for _, name in ipairs(names) do
    if not multiple_of(P[name], P.d0) then
      error(("flume: %s = %g m is not a whole number of particles at d0 = %g m, so the girder "
             .. "would not sit exactly on the pier; use d0 = %g / k (0.005, 0.0075, 0.01, "
             .. "0.015, 0.02, 0.03, ...)"):format(name, P[name], P.d0, lattice_unit), 0)
    end
  end
  if not multiple_of(overhang, P.d0) or (P.dim == 3 and
      not multiple_of(0.5 * (P.flume_width - P.pier_width), P.d0)) then
    error(("flume: the girder's overhang beyond the pier (girder_width - pier_length)/2 = %g m, "
           .. "or the pier's offset from the side walls, is not a whole number of particles at "
           .. "d0 = %g m"):format(overhang, P.d0), 0)
  end
end

-- Builds the flume into the scene and returns its key positions (metres):
--   { gate_x, pier_x0, pier_x1, pier_top, girder = {min, max}, girder_centre, centre_y,
--     window_x, materials = {girder, pier, wall} }
function flume.build(P)
  local ok, message = pcall(flume.check, P)
  if not ok then error(message, 2) end  -- reported at the scene's call of flume.build
  local g = 9.81  -- the engine's default gravity (docs/parameters.md) when the scene sets none
  if #P.gravity > 0 then
    g = 0
    for _, c in ipairs(P.gravity) do g = g + c * c end
    g = math.sqrt(g)
  end
  local pla = washout.material { name = flume.girder_material.name, E = P.girder_young_modulus,
                                 nu = flume.girder_material.nu, eps = P.girder_restitution }
  local pier_mat = washout.material(flume.pier_material)
  local glass = washout.material(flume.wall_material)
  washout.friction { pla, pier_mat, flume.mu_girder_pier }
  washout.friction { pla, glass, flume.mu_girder_wall }

  local L, Hw, H = P.flume_length, P.wall_height, P.water_height
  local x_gate = P.reservoir_length
  local t_gate = tank.wall_thickness(P)  -- [assumption] the kernel needs 3 layers; a real gate is thinner
  local px0 = x_gate + P.pier_distance
  local px1 = px0 + P.pier_length
  local overhang = 0.5 * (P.girder_width - P.pier_length)
  local gx0, gx1 = px0 - overhang, px1 + overhang
  local gz0, gz1 = P.pier_height, P.pier_height + P.girder_height
  -- Free fall: z(t) = g t^2 / 2 until the gate is out of the flume, then it stays there (a gate
  -- climbing for ever would take the neighbour grid with it).
  -- A gate_speed > 0 lifts it at that constant speed instead.
  local function lift(t)
    if P.gate_speed > 0 then return math.min(P.gate_speed * t, P.gate_lift) end
    return math.min(0.5 * g * t * t, P.gate_lift)
  end

  local out = { gate_x = x_gate, pier_x0 = px0, pier_x1 = px1, pier_top = gz0,
                window_x = px0 + P.window_length }
  if P.dim == 2 then
    washout.fluid { washout.box { min = { 0, 0 }, max = { x_gate, H } } }
    washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { L, Hw } }), name = "flume",
                   material = glass }
    washout.moving_wall { washout.box { min = { x_gate, 0 }, max = { x_gate + t_gate, Hw } },
                          name = "gate",
                          motion = function(t) return { 0, lift(t) } end }
    washout.wall { washout.box { min = { px0, 0 }, max = { px1, gz0 } }, name = "pier",
                   material = pier_mat }
    out.girder = { min = { gx0, gz0 }, max = { gx1, gz1 } }
    washout.body { washout.box(out.girder), name = "girder", density = P.girder_density,
                   material = pla }
    out.girder_centre = { 0.5 * (gx0 + gx1), 0.5 * (gz0 + gz1) }
  else
    local W = P.flume_width
    local py0 = 0.5 * (W - P.pier_width)
    washout.fluid { washout.box { min = { 0, 0, 0 }, max = { x_gate, W, H } } }
    washout.wall { tank.open_box(P, { min = { 0, 0, 0 }, max = { L, W, Hw } }), name = "flume",
                   material = glass }
    washout.moving_wall { washout.box { min = { x_gate, 0, 0 }, max = { x_gate + t_gate, W, Hw } },
                          name = "gate",
                          motion = function(t) return { 0, 0, lift(t) } end }
    washout.wall { washout.box { min = { px0, py0, 0 }, max = { px1, py0 + P.pier_width, gz0 } },
                   name = "pier", material = pier_mat }
    -- [assumption] The girder spans the flume from glass wall to glass wall, touching both
    -- (the paper's girder-wall friction 0.0 is for its ends sliding on the glass).
    out.girder = { min = { gx0, 0, gz0 }, max = { gx1, W, gz1 } }
    washout.body { washout.box(out.girder), name = "girder", density = P.girder_density,
                   material = pla, angle_axis = "y" }
    out.girder_centre = { 0.5 * (gx0 + gx1), 0.5 * W, 0.5 * (gz0 + gz1) }
    out.centre_y = 0.5 * W
  end
  out.materials = { girder = pla, pier = pier_mat, wall = glass }
  return out
end

-- Probes along the flume: the water depth in the reservoir and just upstream of the pier, and
-- the surge front. The pier probe sits one girder overhang plus d0 upstream of the pier, on the
-- centreline, so that it reads the water arriving at the girder's upstream face.
function flume.probes(P, f)
  local function at(x)
    if P.dim == 2 then return { x, 0 } end
    return { x, f.centre_y, 0 }
  end
  washout.probe { name = "depth_reservoir", quantity = "water_height",
                  at = at(0.5 * P.reservoir_length) }
  washout.probe { name = "depth_pier", quantity = "water_height",
                  at = at(f.girder.min[1] - P.d0) }
  washout.probe { name = "front", quantity = "front", axis = "x" }
end

-- Stops the run once the girder's centre of mass has left the observation window downstream.
function flume.stop_when_girder_leaves(f)
  washout.on_step(function(s)
    local g = s.bodies.girder
    if g and g.position[1] > f.window_x then
      washout.stop(("the girder left the observation window (x > %.2f m)"):format(f.window_x))
    end
  end)
end

return flume
