-- Paper section 5.2, case 3 / section 5.3: the Manchester R = 500 m track with irregularities.
-- The paper generates them from analytic PSDs (its ref. [35]) without naming the spectrum or the
-- band; we use ORE B176 "low disturbance" (issue 6) over 3..70 m wavelengths (EN 13848 D1+D2)
-- with a fixed seed. Assumptions, stated: spectrum level, band, seed, 2000 cosines per channel.
local lib = require "tracks.lib"

track {
  segments = lib.manchester_r500(),
  step = 0.5,
  irregularities = psd {
    spectrum = "ore_b176_low",
    seed = 42,
    wavelengths = { 3, 70 },
    step = 0.1,            -- paper section 2.1
    fade_in = 0,           -- the paper's start, without the default 20 m ramp (docs/track.md)
  },
}
