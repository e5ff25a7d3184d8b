-- A check rail in a sharp curve (tests/run/test_check_rail.cpp; docs/sliced_rails.md, "Check
-- rails"): the Manchester wagon 1 at 16 m/s through the R = 150 m left curve of the hard-case
-- suite (scenarios/hard/sharp_curve.lua: no cant, V^2/R = 1.7 m/s^2 of cant deficiency), S1002
-- on 60E1 at 1:40 (scenarios/validation/common.lua), elastic contact; with or without a check
-- rail beside the inner (left) rail over the first 140 m.
-- ASSUMPTIONS: the check rail is a 60E1 head (the built-in profile, inclined 1:40 as the running
-- rail is) whose face lies a flangeway of 41 mm from the running rail's gauge face (the
-- flangeway of the shipped crossing scene, scenarios/turnout/lib.lua): its profile origin is
-- moved toward the track centre by the 36.0 mm half head of 60E1, the 35.5 mm from the running
-- rail's origin to its gauge point and the 41 mm.
local hard = require "hard.lib"
return function(with_check_rail)
  hard.curve_track(150, { curve = 100 })
  local dy = -(0.0360 + 0.0355 + 0.041)
  profiles { wheel = "s1002", rail = "60e1", back_to_back = 1.360, gauge = 1.435, r0 = 0.46,
             inclination = 0.025,
             extra_rails = with_check_rail and { left = { { name = "check", check = true,
               slices = { { s = 0, rail = "60e1", dy = dy }, { s = 140, rail = "60e1", dy = dy } } } } }
               or nil }
  contact { method = "elastic", creep = "polach", mu = hard.MU_PAPER }
  vehicle (require "vehicles.manchester_wagon1" { speed = 16 })
  solver { method = "abm", step = 2.5e-4 }
  run { duration = 4, output = { every = 0.01 } }
end
