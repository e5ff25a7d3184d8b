-- Paper section 5.2, case 2: Manchester wagon track without irregularities: 100 m tangent, 50 m
-- transition, 350 m left curve R = 500 m (Fig. 18).
local lib = require "tracks.lib"

track {
  segments = lib.manchester_r500(),
  step = 0.5,
}
