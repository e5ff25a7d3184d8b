-- Paper section 5.2, case 1: single wheelset track, 30 m tangent + 50 m transition + 40 m left
-- curve of radius R = 300 m, no irregularities. Centreline splined every 0.5 m (paper section 2.1).
local lib = require "tracks.lib"

track {
  segments = lib.validation(300),
  step = 0.5,
}
