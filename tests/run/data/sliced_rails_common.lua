-- The Manchester wagon 1 (scenarios/vehicles/manchester_wagon1.lua) at 20 m/s on a tangent without
-- irregularities, S1002 on a 60E1 rail read from a point file (rails/60e1_a.txt, sampled from the
-- built-in 60E1), elastic contact, with the rail slices and further rails a scene gives
-- (tests/run/test_sliced_rails.cpp). The wheelsets start at s = 8.4 .. 30 m.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
return function(slices, duration, extra)
  track { segments = { tangent { length = 300 } }, step = 0.5 }
  profiles { wheel = "s1002", rail = "rails/60e1_a.txt", back_to_back = 1.360, gauge = 1.435,
             r0 = 0.46, inclination = 0.025, rail_slices = slices,
             extra_rails = extra }
  contact { method = "elastic", creep = "polach", mu = 0.2364 }
  vehicle (wagon { speed = 20, start = 30 })
  c.abm(20, 5e-4)
  run { output = { every = 0.01 }, duration = duration }
end
