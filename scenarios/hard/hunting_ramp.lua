-- Hard case 4b: speed ramp through the critical hunting speed on tangent track (issue 7 item 4),
-- Manchester wagon 1. Needs the engine's vehicle.acceleration key (speed V(t) = V0 + a t, being
-- added in issue 7); until it exists the suite skips this case (tests/hard/hard_cases.py checks
-- `workbench help scenario`).
-- Excitation: ORE B176 low irregularities (paper section 5.2, seed 42) scaled by 0.1, as in
-- hunting.lua.
-- ASSUMPTION: V0 = 50 m/s, a = 1 m/s^2 for 35 s, i.e. 50 -> 85 m/s, bracketing the critical
-- speed measured with hunting.lua (stable at 70 m/s, hunting at 75 m/s, docs/hard_cases.md); the
-- run covers 50 t + t^2/2 = 2362.5 m.
local hard = require "hard.lib"
track {
  segments = { tangent { length = 2500 } },
  step = 0.5,
  irregularities = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 }, step = 0.1,
                         scale = 0.1 },
}
hard.profiles()
contact { method = "kec", creep = "polach", mu = hard.MU_PAPER }
local v = (require "vehicles.manchester_wagon1") { speed = 50 }
v.acceleration = 1.0   -- [m/s^2] ASSUMPTION (see header)
vehicle (v)
solver { method = "dopri5" }
run { duration = 35, output = { every = 0.01 },
      -- EN 14363 safety and stability, EN 12299 / Sperling comfort, T gamma wear (docs/assessment.md);
      -- a quantity needing more track (100 m) or time (5 s) than the case runs is left out.
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
