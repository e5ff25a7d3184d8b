-- Side buffers and screw-coupling draw gear between two passenger coaches, for train{}
-- connections:
--   local couplings = require "train.couplings"
--   connections = { couplings.screw("loco", "wagon1", { slack = 0.01 }), ... }
--
-- Every number here is an ASSUMPTION of a UIC-type buffered, screw-coupled vehicle, not data of a
-- particular product (none was at hand):
-- - buffer spacing 1.75 m and height 1.06 m: the nominal values of UIC-buffered stock (UIC 527-1
--   gives 1750 mm between buffer centres; buffer height 940-1065 mm above rail);
-- - buffer force-stroke: a category-A side buffer with 105 mm stroke (UIC 526-1 asks for at least
--   30 kJ of absorbed energy): the loading curve below stores 29 kJ at full stroke, stiffening
--   from 2.5 MN/m to 28 MN/m; the unloading curve gives back 40 % of the loading force (a
--   ring-spring buffer dissipates about 60 % of its energy);
-- - buffer-head friction coefficient 0.2 (greased steel heads);
-- - draw gear: 5 MN/m with 20 % friction hysteresis at 1.06 m, slack as the caller gives it (0: a
--   tightened screw coupling);
-- - headstocks 12.5 m in front of and behind the car body's centre (a 25 m coach over buffers, as
--   scenarios/train/three_wagons.lua places the Manchester wagons).
local M = {}

local loading = { { 0, 0 }, { 0.02, 50e3 }, { 0.05, 150e3 }, { 0.08, 400e3 }, { 0.105, 1000e3 } }
local function unloading()
  local out = {}
  for i, p in ipairs(loading) do out[i] = { p[1], 0.4 * p[2] } end
  return out
end

function M.screw(front, rear, opts)
  opts = opts or {}
  return {
    front = front, rear = rear,
    front_end = -(opts.half_length or 12.5), rear_end = opts.half_length or 12.5,
    buffers = { loading = loading, unloading = unloading(), spacing = 1.75, height = 1.06,
                friction = opts.buffer_friction or 0.2 },
    draw_gear = { stiffness = opts.draw_stiffness or 5e6, slack = opts.slack or 0,
                  friction = 0.2, height = 1.06 },
  }
end

return M
