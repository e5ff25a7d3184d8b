-- Hard case 5: a wheel-climb situation (issue 7 item 4), Manchester wagon 1.
-- Flange climb (Nadal): the outer wheel of the leading wheelset climbs when Y/Q exceeds
--   (tan(gamma) - mu) / (1 + mu tan(gamma)),
-- with gamma the flange angle (S1002 flank: 70 deg, docs/creep.md, docs/contact_geometry.md).
-- With dry rail mu = 0.5
-- (ASSUMPTION: a dry-rail value; the paper uses 0.2364) the limit is 0.95.
-- ASSUMPTION: the situation that drives Y/Q up is a very sharp curve at low speed with dry rail:
-- R = 100 m, no cant, V = 5 m/s (18 km/h): the leading wheelset runs with a large angle of attack
-- (wheelbase 2.56 m on R = 100 m), the lateral creep force of the outer wheel points outwards and
-- adds to the flange force. The test checks that Y/Q stays finite and bounded and that the run
-- either ends normally or stops with the clean failure of docs/integrators.md (a wheel leaving
-- the contact table is a recoverable rhs failure that becomes such a failure).
local hard = require "hard.lib"
hard.curve_track(100, { tangent = 5, transition = 10, curve = 100 })
hard.profiles()
contact { method = "kec", creep = "polach", mu = 0.5 }
vehicle (require "vehicles.manchester_wagon1" { speed = 5 })
solver { method = "dopri5" }
-- Short: 6 s = 30 m: 5 m tangent, 10 m transition, 15 m of the curve.
run { duration = 6, output = { every = 0.01 },
      -- EN 14363 safety and stability, EN 12299 / Sperling comfort, T gamma wear (docs/assessment.md);
      -- a quantity needing more track (100 m) or time (5 s) than the case runs is left out.
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
