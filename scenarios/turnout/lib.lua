-- The rails of a right-hand turnout of 60E1 rails with a switch radius of 190 m and a 1:9 crossing
-- (the layout of a "60E1-190-1:9" turnout) as railbench slices (profiles.rail_slices and
-- profiles.extra_rails, docs/turnouts.md): the switch panel of the diverging route (its outer,
-- left rail: the straight stock rail and the curved switch blade). Every rail is drawn in its
-- side's rail frame (dy toward the field side, dz up); x is the distance along the route from the
-- toe.
--
-- Switch panel (diverging route, left rail), x from the toe:
--   stock rail (the running rail "rail"): the straight stock rail seen from the curved route,
--     dy = x^2 / (2 R_L), R_L = 190 + 0.7175 m the left rail's radius (the exact offset
--     R_L - sqrt(R_L^2 - x^2) differs by x^4 / (8 R_L^3) < 0.1 mm here), slices every 1 m;
--   "blade": the curved switch blade, its gauge face on the route's running line and its field
--     side against the stock rail's gauge face, so its width is the stock rail's offset; from a
--     width of 1 mm (x = 0.62 m) to the full 72 mm head (x = 5.24 m), then the closure rail.
-- The crossing (a wing rail diverging at 1:9 from under the wheel and a rising nose) is not part
-- of the shipped scene: on the diverging route a check rail on the other side keeps the outer
-- wheel's flange off the nose, and on rigid rails the wheel falls off the wing and is launched
-- by the nose (docs/turnouts.md, "Not yet").
-- ASSUMPTIONS (no drawing of a turnout was available): the blade's top 8 mm below the stock
-- rail's where it is 5 mm wide, level from 45 mm width on (linear in the width); the blade's top
-- is the 60E1 head cut to its width (slices/head_wNN.txt, make_slices.py), blended linearly
-- between the widths of those files; the crossing's theoretical point 23.5 m after the toe (where
-- the route's outer rail, curved over 21.1 m and then straight at 1:9, meets the through route's
-- other rail 1.435 m away); rigid rails.
local M = {}

M.radius = 190                           -- [m] switch radius (the route's centreline)
M.left_radius = 190 + 1.435 / 2          -- [m] the diverging route's outer (left) rail
M.curve_length = 190 * math.atan(1 / 9)  -- [m] the curve over the crossing angle (21.04 m)
M.crossing = 23.5                        -- [m] the crossing's theoretical point after the toe
-- [mm] the widths of slices/head_wNN.txt (make_slices.py): 1 to 6, then every 2 mm to 70
local widths = { 1, 2, 3, 4, 5, 6 }
for w = 8, 70, 2 do widths[#widths + 1] = w end
local full = 72                          -- [mm] the 60E1 head's width

local function head(w)
  if w >= full then return "slices/60e1.txt" end
  return string.format("slices/head_w%02d.txt", w)
end

-- The diverging route's track: tangent, the turnout's curve from the toe, tangent.
function M.diverging_track(toe, after)
  return { tangent { length = toe },
           curve { length = M.curve_length, radius = M.radius, side = "right" },
           tangent { length = after } }
end

-- The switch panel's rails of the diverging route's left side, the toe at s = toe: the stock rail
-- (running rail slices) and the blade (a further rail), which runs on as the closure rail to
-- s = till.
function M.switch_rails(toe, till)
  local stock = {}
  for x = 0, 12 do
    stock[#stock + 1] = { s = toe + x, rail = head(full), dy = x * x / (2 * M.left_radius) }
  end
  -- Far from the wheels from here on (0.38 m at 12 m): it stays aside.
  stock[#stock + 1] = { s = toe + 16, rail = head(full), dy = 0.5 }
  local blade = {}
  local function blade_dz(w) return w < 45 and -0.008 * (45 - w) / 40 or 0 end
  for _, w in ipairs(widths) do
    blade[#blade + 1] = { s = toe + math.sqrt(2 * M.left_radius * w * 1e-3), rail = head(w),
                          dz = blade_dz(w) }
  end
  blade[#blade + 1] = { s = toe + math.sqrt(2 * M.left_radius * full * 1e-3), rail = head(full) }
  blade[#blade + 1] = { s = till, rail = head(full) }
  return stock, { name = "blade", slices = blade }
end

-- The common crossing of the through route's right rail (docs/turnouts.md, "The crossing"), its
-- theoretical point (where the nose's two gauge lines meet) at s = tp: the wing rail (the running
-- rail's slices) runs on the wheel's line up to the knuckle, then diverges to the field side at
-- the crossing angle (1:9); the nose (a further rail, "nose") starts where it is nose_tip wide, its
-- gauge face on the running line and its width growing at 1:9, and runs on as the through route's
-- rail to s = till. The flangeway between the nose's field side and the wing rail's gauge face is
-- M.flangeway, so the knuckle lies 9 M.flangeway before the theoretical point.
-- ASSUMPTIONS (no drawing of a crossing was available): flangeway 41 mm; the nose's actual tip 10 mm
-- wide (0.09 m after the theoretical point); its top 6 mm below the wing rail's there, level from
-- 40 mm width (linear in the width); the wing rail level, a 60E1 head; rigid or flexible track as
-- the scene says.
M.flangeway = 0.041  -- [m]
M.nose_tip = 10      -- [mm]
function M.crossing_rails(tp, till)
  local knuckle = tp - 9 * M.flangeway
  local wing = { { s = knuckle, rail = head(full) },
                 { s = knuckle + 3, rail = head(full), dy = 3 / 9 } }
  local function nose_dz(w) return w < 40 and -0.006 * (40 - w) / 30 or 0 end
  local nose = {}
  for _, w in ipairs(widths) do
    if w >= M.nose_tip then
      nose[#nose + 1] = { s = tp + 9 * w * 1e-3, rail = head(w), dz = nose_dz(w) }
    end
  end
  nose[#nose + 1] = { s = tp + 9 * full * 1e-3, rail = head(full) }
  nose[#nose + 1] = { s = till, rail = head(full) }
  return wing, { name = "nose", slices = nose }
end

return M
