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
--                 2.09-3.70, i.e. -21 % to +40 % of the median. Reported, no bound: an
--                 incompressible model stops the arriving water within a step or two, so its
--                 peak is that impulse over the step and changes with it (docs/method.md,
--                 the twenty-third session);
--   pressure_impulse  the impact's impulse at sensor 1, I = integral of p* d tau from the
--                 onset (p* first above 0.5) over the experiment's impact phase (from its
--                 onset until its median has fallen to half its peak: 0.365 in tau), against
--                 the median's I over the same phase (0.668), as a fraction of the band's
--                 half-width on that side (the same integral of the 2.5 % and 97.5 % curves,
--                 0.581-0.814): 1 is the band's edge. What the water gives a structure on impact;
--                 unlike the peak it does not depend on the step.
-- Sensor 1 is on the downstream wall 3 mm above the floor; the probe sits on the wall face.
-- Bounds: what the engine reaches at d0 = 0.01 and 0.005 m with a margin; the impulse's, the
-- experiment's band.
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
-- In a list: pairs() over names would make the probes (and the checkpoint's order of their
-- values) in an order that changes from run to run.
local gauges = { { "H1", 0.300 }, { "H2", 0.865 }, { "H3", 1.114 }, { "H4", 1.3625 } }
for _, gauge in ipairs(gauges) do
  washout.probe { name = gauge[1], quantity = "water_height", at = { gauge[2], 0 } }
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
  -- No bound: the arriving water is stopped within a step or two, so the peak (9.6 at d0 =
  -- 0.01 m) is that impulse over the step and changes with it (5.9 at half the step); the
  -- impact is held to its impulse below (docs/method.md, the twenty-third session).
  error = validation.peak {
    probe = "sensor1", window = { 1.5, 3.5 }, reference = median_peak, relative = true,
    transform = function(t, p) return t * tau, p / rho_g_H end,
  },
}

-- The impact phase, read off the experiment's median: from its onset to its fall to half peak.
local onset_level, search = 0.5, { 1.5, 3.5 }
local onset = validation.onset(s1.tau, s1.s1_median, onset_level, search)
local peak_k = 1
for k = 1, #s1.tau do
  if s1.tau[k] <= search[2] and s1.s1_median[k] > s1.s1_median[peak_k] then peak_k = k end
end
local half_at
for k = peak_k, #s1.tau do
  if s1.s1_median[k] < 0.5 * s1.s1_median[peak_k] then half_at = s1.tau[k]; break end
end
local phase = half_at - onset
local function measured(column)
  return (validation.impact_impulse(s1.tau, s1[column], onset_level, phase, search))
end
local median_impulse = measured("s1_median")
local low, high = measured("s1_p025"), measured("s1_p975")
washout.validation {
  name = "pressure_impulse",
  metric = string.format("I = integral of p* d tau at sensor 1 over %.3f in tau from the " ..
                         "onset (p* > %.1f), against the median's %.3f: the distance as a " ..
                         "fraction of the experiment's 2.5-97.5 %% band on that side, " ..
                         "%.3f-%.3f (1 = the band's edge)", phase, onset_level,
                         median_impulse, low, high),
  reference = "Lobovsky et al. (2014) sensor 1 median (lobovsky2014_H300_pressure_s1.csv)",
  bound = 1.0,
  error = validation.impulse {
    probe = "sensor1", window = search, onset = onset_level, duration = phase,
    reference = median_impulse, band = { low, high },
    transform = function(t, p) return t * tau, p / rho_g_H end,
  },
}
