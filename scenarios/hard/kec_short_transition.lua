-- Hard case 2: KEC with very short tread-flange transition lengths (issue 7 item 4).
-- The KEC bridges the jump of the contact point between tread and flange over the transition
-- lengths dhat (flange side) and dbar (tread side) (paper section 2.4: 0.5 mm / 1 mm). Shorter
-- transitions make the contact-point jump sharper and the equations stiffer.
-- ASSUMPTION: dhat = dbar = 0.1 mm, the shortest length named in issue 7 (the schema allows
-- (0, 10 mm]), on the sharp-curve set-up of sharp_curve.lua (R = 150 m, no cant, V = 16 m/s,
-- Manchester wagon 1), where the leading wheelset goes through the tread-flange transition into
-- two-point contact within the first second.
local hard = require "hard.lib"
hard.curve_track(150)
hard.profiles()
contact { method = "kec", dhat = 1e-4, dbar = 1e-4, creep = "polach", mu = hard.MU_PAPER }
vehicle (require "vehicles.manchester_wagon1" { speed = 16 })
solver { method = "dopri5" }
run { duration = 3, output = { every = 0.01 },
      -- EN 14363 safety and stability, EN 12299 / Sperling comfort, T gamma wear (docs/assessment.md);
      -- a quantity needing more track (100 m) or time (5 s) than the case runs is left out.
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
