-- Shared track layouts of the founding paper (Yu et al., section 5.2), used through
--   local lib = require "tracks.lib"
-- Assumption (not stated in the paper): the tracks have no cant and no gradient; the paper gives
-- only segment lengths and radii (Fig. 16, 18).
local M = {}

-- Case 1: single wheelset, 30 m tangent, 50 m transition, 40 m left curve (paper Fig. 16).
function M.validation(radius)
  return {
    tangent    { length = 30 },
    transition { length = 50, radius = radius, side = "left" },
    curve      { length = 40, radius = radius, side = "left" },
  }
end

-- Cases 2 and 3: Manchester wagon, 100 m tangent, 50 m transition, 350 m left curve R = 500 m
-- (paper Fig. 18).
function M.manchester_r500()
  return {
    tangent    { length = 100 },
    transition { length = 50, radius = 500, side = "left" },
    curve      { length = 350, radius = 500, side = "left" },
  }
end

return M
