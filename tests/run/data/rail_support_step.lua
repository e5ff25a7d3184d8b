-- rail_support_tangent.lua's wagon on a track under the rail whose vertical stiffness varies along
-- s (contact.elastic.rail_support.along): 100 MN/m, doubled linearly over s = 45 .. 55 m, then
-- 800 MN/m from s = 60.05 m on (a step over 5 cm, 2.5 ms at 20 m/s). Light support damping
-- (2 kN s/m) so that the vertical modes ring after the step. The leading wheelset starts at
-- s = 40.78 m and passes the step at t = 0.96 s. tests/run/test_rail_support.cpp.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } }, step = 0.5 }
profiles { wheel = "s1002", rail = "60e1", back_to_back = 1.360, gauge = 1.435, r0 = 0.46,
           inclination = 0.025 }
contact { method = "elastic", creep = "polach", mu = 0.2364,
          elastic = { rail_support = { mass = 150, k_z = 1e8, c_z = 2e3, k_y = 4e7, c_y = 5e4,
                                       along = { { s = 45 }, { s = 55, k_z = 2e8 },
                                                 { s = 60, k_z = 2e8 }, { s = 60.05, k_z = 8e8 } } } } }
vehicle (wagon { speed = 20, start = 30 })
c.abm(20, 1e-4)
run { output = { every = 5e-4 }, duration = 1.3 }
