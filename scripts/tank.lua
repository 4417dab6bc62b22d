-- Shared geometry: open-top rectangular tanks made of wall boxes around an inner region.
-- Walls are as thick as the kernel needs (wall_layers, or ceil(2 h / d0) layers when 0), so a
-- user changes the inner size only. Coordinates are SI metres; the last axis is vertical.
local tank = {}

-- Thickness of a wall in metres for the resolved parameters P.
function tank.wall_thickness(P)
  local layers = P.wall_layers
  if layers == 0 then layers = math.ceil(2 * P.h_over_d0 - 1e-9) end
  return layers * P.d0
end

-- An open-top tank: floor and side walls around inner = {min = {...}, max = {...}}.
-- The side walls rise to inner.max's vertical coordinate.
function tank.open_box(P, inner)
  local t = tank.wall_thickness(P)
  local lo, hi = inner.min, inner.max
  if P.dim == 2 then
    return washout.union {
      washout.box { min = { lo[1] - t, lo[2] - t }, max = { hi[1] + t, lo[2] } },  -- floor
      washout.box { min = { lo[1] - t, lo[2] }, max = { lo[1], hi[2] } },          -- left
      washout.box { min = { hi[1], lo[2] }, max = { hi[1] + t, hi[2] } },          -- right
    }
  end
  return washout.union {
    washout.box { min = { lo[1] - t, lo[2] - t, lo[3] - t }, max = { hi[1] + t, hi[2] + t, lo[3] } },
    washout.box { min = { lo[1] - t, lo[2] - t, lo[3] }, max = { lo[1], hi[2] + t, hi[3] } },
    washout.box { min = { hi[1], lo[2] - t, lo[3] }, max = { hi[1] + t, hi[2] + t, hi[3] } },
    washout.box { min = { lo[1], lo[2] - t, lo[3] }, max = { hi[1], lo[2], hi[3] } },
    washout.box { min = { lo[1], hi[2], lo[3] }, max = { hi[1], hi[2] + t, hi[3] } },
  }
end

-- Two parallel plates across the vertical axis (a channel, periodic along the flow), lower
-- plate top at y = y0 and upper plate bottom at y = y1, spanning x in [x0, x1].
function tank.plates(P, x0, x1, y0, y1)
  local t = tank.wall_thickness(P)
  return washout.union {
    washout.box { min = { x0, y0 - t }, max = { x1, y0 } },
    washout.box { min = { x0, y1 }, max = { x1, y1 + t } },
  }
end

return tank
