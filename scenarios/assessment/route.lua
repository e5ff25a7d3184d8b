-- A route as an EN 14363 on-track test would run it, for the per-section assessment of
-- docs/assessment.md ("A route, section by section"): Manchester wagon 1 at 25 m/s (90 km/h)
-- over a tangent, a left curve of R = 600 m (test zone 2), a tangent, a right curve of R = 350 m
-- (test zone 4), and a tangent, every curve entered and left through a clothoid transition with a
-- linear cant ramp; ORE B176 low irregularities (seed 7) faded in over the first 20 m (the
-- default track.irregularities.fade_in).
-- ASSUMPTIONS (a route made up for the page, not a real line): cants 80 mm (R = 600 m) and
-- 150 mm (R = 350 m) give cant deficiencies of 0.52 and 0.81 m/s^2 at 25 m/s (a = V^2/R -
-- g u / 1.5 m), inside the 1.0 m/s^2 usual for conventional vehicles; transition lengths 60 and
-- 80 m (cant ramps of 1.3 and 1.9 mm/m). Contact, profiles and solver as the paper's case 3
-- (validation.common).
local common = require "validation.common"

track {
  segments = {
    tangent    { length = 100 },
    transition { length = 60, radius = 600, side = "left", cant = 0.080 },
    curve      { length = 200, radius = 600, side = "left", cant = 0.080 },
    transition { length = 60 },
    tangent    { length = 80 },
    transition { length = 80, radius = 350, side = "right", cant = 0.150 },
    curve      { length = 200, radius = 350, side = "right", cant = 0.150 },
    transition { length = 80 },
    tangent    { length = 120 },
  },
  step = 0.5,
  irregularities = psd { spectrum = "ore_b176_low", seed = 7, wavelengths = { 3, 70 }, step = 0.1 },
}
common.profiles()
common.contact("kec")
vehicle (require "vehicles.manchester_wagon1" { speed = 25, start = 15 })
common.abm(25)
run {
  output = { every = 0.01 },
  assessment = { safety = true, stability = true, comfort = true, wear = true },
}
