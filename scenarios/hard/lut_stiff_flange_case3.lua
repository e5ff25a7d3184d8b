-- Hard case 1 (long): the paper's own K = 7.075e13 N/m^1.5 set-up (section 5.3, Table 7): LUT,
-- Manchester wagon 1 at 20 m/s on the 500 m track of Fig. 18 (100 m tangent, 50 m transition,
-- 350 m left curve R = 500 m) with ORE B176 low irregularities (seed 42), D = K/100 (Table 3).
-- The paper: RK4 and ABM at 1 ms fail when flange contact occurs, ode45 succeeds only with
-- tol <= 1e-8, ode15s with tol <= 1e-7. Everything but the flange constants is case 3
-- (scenarios/validation/case3_lut.lua, common.lua).
local lib = require "tracks.lib"
local hard = require "hard.lib"
track {
  segments = lib.manchester_r500(),
  step = 0.5,
  -- fade_in = 0: case 3's irregularities as the paper's (no ramp at the start).
  irregularities = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 }, step = 0.1,
                         fade_in = 0 },
}
hard.profiles()
contact { method = "lut", flange_stiffness = hard.K_HERTZ, flange_damping = hard.D_HERTZ,
          creep = "polach", mu = hard.MU_PAPER }
vehicle (require "vehicles.manchester_wagon1" { speed = 20 })
solver { method = "dopri5" }
-- 500 m minus the wagon's leading axle position (10.78 m) at 20 m/s, as case 3.
run { duration = 24.461, output = { every = 0.01 },
      -- EN 14363 safety and stability, EN 12299 / Sperling comfort, T gamma wear (docs/assessment.md);
      -- a quantity needing more track (100 m) or time (5 s) than the case runs is left out.
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
