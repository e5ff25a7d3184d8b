-- Hard case 3: sharp curve with sustained flange contact (issue 7 item 4), Manchester wagon 1.
-- ASSUMPTION: R = 150 m (a sharp curve, 1/3.3 of the paper's R = 500 m; no standard cited),
-- no cant, V = 16 m/s (58 km/h): lateral acceleration V^2/R = 1.7 m/s^2, all of it
-- cant deficiency, so the leading wheelsets run against the outer flange for the whole curve.
-- Smooth track (no irregularities): the flange contact is quasi-static, sustained, not impacts.
-- KEC with the paper's transition lengths dhat = 0.5 mm, dbar = 1 mm (section 2.4); the suite
-- also runs it with contact.method=lut (K = 1e10 N/m^1.5, D = K/100: the validation setting).
local hard = require "hard.lib"
hard.curve_track(150)
hard.profiles()
-- Only keys both methods accept (defaults: dhat 0.5 mm, dbar 1 mm, K 1e10, D K/100), so
-- --set contact.method=lut works.
contact { method = "kec", creep = "polach", mu = hard.MU_PAPER }
vehicle (require "vehicles.manchester_wagon1" { speed = 16 })
solver { method = "dopri5" }
-- Short: 4 s = 64 m: 10 m tangent, 20 m transition, 34 m of the curve; the leading wheelset is in
-- two-point (tread + flange) contact from t ~ 0.5 s on, with ~30 kN on the flange.
run { duration = 4, output = { every = 0.01 },
      -- EN 14363 safety and stability, EN 12299 / Sperling comfort, T gamma wear (docs/assessment.md);
      -- a quantity needing more track (100 m) or time (5 s) than the case runs is left out.
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
