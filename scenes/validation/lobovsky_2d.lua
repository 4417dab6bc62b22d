-- Dam break of Lobovsky et al. (2014), H = 0.3 m, in 2D: a column L = 0.6 m long and
-- H = 0.3 m high at the upstream end of a tank 1.61 m long and 0.6 m high collapses on a dry
-- bed and hits the downstream wall. The scene scores itself (docs/validation.md) against the
-- experiment (validation/reference/lobovsky2014_H300_*.csv), in the paper's normalisation
-- tau = t sqrt(g/H), p* = p / (rho g H):
--   front         RMS of (x_front - L)/H against the measured front, tau <= 2.5 (before the
--                 front reaches the wall at (x - L)/H = 3.37);
--   water_levels  RMS of h/H at H1-H4 (x = 0.300, 0.865, 1.114, 1.3625 m) against the mean
--                 of the two measured series, over the run;
--   pressure_peak abs(peak p* at sensor 1 - median measured peak 2.65) / 2.65, the peak over
--                 tau in [1.5, 3.5]; the experiment's 2.5-97.5 % band of the peak is
--                 2.09-3.70, i.e. -21 % to +40 % of the median.
-- Sensor 1 is on the downstream wall 3 mm above the floor; the probe sits on the wall face.
-- Bounds: what the engine reaches at d0 = 0.01 and 0.005 m with a margin.
local tank = require("tank")
local validation = require("validation")

local P = washout.parameters {
  dim = 2,
  d0 = 0.01,               -- H / 30
  end_time = 0.6,          -- tau = 3.4: past the impact peak (tau = 2.46)
  output_interval = 0.02,
  scene = {
    column_length = 0.6,   -- L [m]
    column_height = 0.3,   -- H [m]
    tank_length = 1.61,    -- [m]
    tank_height = 0.6,     -- [m]
  },
}

local L, H, X = P.column_length, P.column_height, P.tank_length
washout.fluid { washout.box { min = { 0, 0 }, max = { L, H } } }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { X, P.tank_height } }), name = "tank" }
washout.probe { name = "front", quantity = "front", axis = "x" }
local gauges = { H1 = 0.300, H2 = 0.865, H3 = 1.114, H4 = 1.3625 }
for name, x in pairs(gauges) do
  washout.probe { name = name, quantity = "water_height", at = { x, 0 } }
end
washout.probe { name = "sensor1", quantity = "pressure", at = { X, 0.003 } }

local g = validation.g(P)
local rho_g_H = P.rho0 * g * H
local tau = math.sqrt(g / H)

local front = validation.csv("lobovsky2014_H300_front.csv")
washout.validation {
  name = "front",
  metric = "RMS of (x_front - L)/H at the measured points, tau = t sqrt(g/H) <= 2.5",
  reference = "Lobovsky et al. (2014) H = 0.3 m front (lobovsky2014_H300_front.csv)",
  bound = 0.2,
  error = validation.series_rms {
    probe = "front", window = { 0, 2.5 }, min_points = 10,
    reference = { x = front.tau_t_sqrt_g_over_H, y = front.xf_minus_L_over_H },
    transform = function(t, x) return t * tau, (x - L) / H end,
  },
}

-- Each gauge against the mean of the measured series that exist for it.
local levels = validation.csv("lobovsky2014_H300_water_levels.csv")
local pieces = {}
for _, name in ipairs({ "H1", "H2", "H3", "H4" }) do
  local series = {}
  for column, values in pairs(levels) do
    if column:sub(1, #name + 1) == name .. "_" then series[#series + 1] = values end
  end
  local mean = {}
  for k = 1, #levels.tau do
    local s = 0
    for _, values in ipairs(series) do s = s + values[k] end
    mean[k] = s / #series
  end
  pieces[#pieces + 1] = {
    probe = name, reference = { x = levels.tau, y = mean },
    transform = function(t, h) return t * tau, h / H end,
  }
end
washout.validation {
  name = "water_levels",
  metric = "RMS of h/H at H1-H4 against the mean measured series, over the run",
  reference = "Lobovsky et al. (2014) water levels (lobovsky2014_H300_water_levels.csv)",
  bound = 0.05,
  error = validation.pooled_rms(pieces),
}

local s1 = validation.csv("lobovsky2014_H300_pressure_s1.csv")
local median_peak = 0
for k = 1, #s1.tau do median_peak = math.max(median_peak, s1.s1_median[k]) end
washout.validation {
  name = "pressure_peak",
  metric = string.format("abs(peak p* - %.2f) / %.2f at sensor 1, tau in [1.5, 3.5]; the " ..
                         "experiment's 2.5-97.5 %% band is -21 %% to +40 %%", median_peak,
                         median_peak),
  reference = "Lobovsky et al. (2014) sensor 1 median peak (lobovsky2014_H300_pressure_s1.csv)",
  -- No bound: the engine's wall pressure has a one-step spike at the impact (p* about 26 at
  -- d0 = 0.01 m), far outside the band; reported, not yet required (docs/validation.md).
  error = validation.peak {
    probe = "sensor1", window = { 1.5, 3.5 }, reference = median_peak, relative = true,
    transform = function(t, p) return t * tau, p / rho_g_H end,
  },
}
