-- The Manchester wagon 1 (scenarios/vehicles/manchester_wagon1.lua) at 20 m/s on a tangent without
-- irregularities, elastic contact, on the track under the rail (contact.elastic.rail_support):
-- per wheel a rail mass of 150 kg on 100 MN/m and 50 kN s/m vertically, 40 MN/m and 50 kN s/m
-- laterally (ASSUMPTION: values of the order of a ballasted track's receptance under one wheel,
-- e.g. Knothe and Grassie, Vehicle System Dynamics 22 (1993) 209-262; the test asserts the model's
-- own statics and dynamics, not these values). tests/run/test_rail_support.cpp.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } }, step = 0.5 }
profiles { wheel = "s1002", rail = "60e1", back_to_back = 1.360, gauge = 1.435, r0 = 0.46,
           inclination = 0.025 }
contact { method = "elastic", creep = "polach", mu = 0.2364,
          elastic = { rail_support = { mass = 150, k_z = 1e8, c_z = 5e4, k_y = 4e7, c_y = 5e4 } } }
vehicle (wagon { speed = 20, start = 30 })
c.abm(20, 1e-4)
run { output = { every = 0.01 }, duration = 1 }
